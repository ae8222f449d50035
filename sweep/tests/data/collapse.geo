// A granular column 0.1 m wide and 0.1 m high against the left wall of a flat box 0.5 m long
// and 0.15 m high, held by a gate during the gravity stage: a dry collapse that runs in about
// a second, for the end-to-end test of `lituya sweep`.
//
//   y = 0.15  +------------------------------------------+  top
//             |                  air                     |
//   y = 0.1   +------+                                   |
//       wall  |column| gate                              |  end
//   y = 0     +------+-----------------------------------+
//           x = 0  x = 0.1                            x = 0.5   bed
Point(1) = {0, 0, 0};
Point(2) = {0.1, 0, 0};
Point(3) = {0.5, 0, 0};
Point(4) = {0.5, 0.15, 0};
Point(5) = {0, 0.15, 0};
Point(6) = {0, 0.1, 0};
Point(7) = {0.1, 0.1, 0};

Line(1) = {1, 2};  // bed under the column
Line(2) = {2, 3};  // bed ahead of the column
Line(3) = {3, 4};  // end
Line(4) = {4, 5};  // top
Line(5) = {5, 6};  // wall above the column
Line(6) = {6, 1};  // wall beside the column
Line(7) = {2, 7};  // gate
Line(8) = {7, 6};  // column top

Curve Loop(1) = {1, 7, 8, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, 5, -8, -7};
Plane Surface(2) = {2};

Physical Surface("column") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1, 2};
Physical Curve("walls") = {3, 5, 6};
Physical Curve("top") = {4};
Physical Curve("gate") = {7};
