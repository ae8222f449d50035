// Plane-strain granular column 1 m wide and 2 m high (aspect ratio a = H / L = 2) against a
// vertical wall at x = 0, on a no-slip bed y = 0, in an empty mesh 7 m long and 2.2 m high.
L = 1.0;  H = 2.0;  length = 7.0;  top = 2.2;
Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {length, 0, 0};
Point(4) = {length, top, 0};
Point(5) = {0, top, 0};
Point(6) = {0, H, 0};
Point(7) = {L, H, 0};
Line(1) = {1, 2};   // bed under the column
Line(2) = {2, 3};   // bed ahead
Line(3) = {3, 4};   // end
Line(4) = {4, 5};   // top
Line(5) = {5, 6};   // wall above the column
Line(6) = {6, 1};   // wall beside the column
Line(7) = {2, 7};   // column face (internal)
Line(8) = {7, 6};   // column top (internal)
Curve Loop(1) = {1, 7, 8, 6};
Plane Surface(1) = {1};            // column
Curve Loop(2) = {2, 3, 4, 5, -8, -7};
Plane Surface(2) = {2};            // air
Physical Surface("column") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1, 2};
Physical Curve("wall") = {5, 6};
Physical Curve("end") = {3};
Physical Curve("top") = {4};
