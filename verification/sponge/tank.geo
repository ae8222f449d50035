// Sponge verification tank (README.md): still water h = 0.15 m deep over a flat bed from the
// wall at x = 0 to the end wall at x = L = 3.1 m (tank_long.geo: 10 m, the same mesh up to
// x = L and an extra piece beyond it). Near x = 0 the surface starts displaced by a Ricker
// wavelet a (1 - 2 (x/s)^2) exp(-(x/s)^2), x < 3 s: a crest at the wall between two troughs
// of its mirror image, with no net volume, so the wave it sends down the tank leaves no
// set-up behind it in a closed tank (a single hump's water would have to stay). "air" is
// empty mesh above the water for the wave to rise into.
//
//  y = top  +-------------------------------------------------+
//           |  air                                            |
//  y = h+a  *.                                                |
//           |  `-._ hump                                      |
//  y = h    |       `*------------- still surface ------------+
//           |  water                                          |
//  y = 0    +-------------------------- bed ------------------+
//          x = 0                  x = 3 s                   x = L

h = 0.15;    // still water depth
a = 0.04;    // crest height at the wall (the wave leaving it is about a / 2 high)
s = 0.3;     // wavelet width
L = 3.1;     // tank length
If (!Exists(extension))
  extension = 0;  // tank_long.geo: the tank made longer by a piece beyond x = L
EndIf
top = 0.25;  // top of the mesh
n = 30;      // straight pieces along the wavelet

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, h, 0};
Point(4) = {L, top, 0};
Point(5) = {0, top, 0};
For i In {0:n}
  x = 3 * s * (n - i) / n;  // from x = 3 s (i = 0) to the wall (i = n)
  Point(10 + i) = {x, h + a * (1 - 2 * (x / s)^2) * Exp(-(x / s)^2), 0};
EndFor

Line(1) = {1, 2};           // bed
Line(2) = {2, 3};           // end wall beside the water
Line(3) = {3, 10};          // still surface from the end wall to the wavelet
Line(4) = {10 + n, 1};      // wall at x = 0 beside the water
Line(5) = {3, 4};           // end wall above the water
Line(6) = {4, 5};           // top
Line(7) = {5, 10 + n};      // wall at x = 0 above the water
hump[] = {};
back[] = {};
For i In {0:n - 1}
  Line(100 + i) = {10 + i, 11 + i};
  hump[] += {100 + i};
  back[] += {-(100 + n - 1 - i)};
EndFor

Curve Loop(1) = {1, 2, 3, hump[], 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, back[], -3};
Plane Surface(2) = {2};

If (extension > 0)
  // The piece beyond x = L: surfaces of their own, so the mesh up to x = L is the same as
  // without them (the gauge records differ only by what the tank end sends back).
  Point(6) = {L + extension, 0, 0};
  Point(7) = {L + extension, h, 0};
  Point(8) = {L + extension, top, 0};
  Line(20) = {2, 6};   // bed
  Line(21) = {6, 7};   // end wall beside the water
  Line(22) = {7, 3};   // still surface
  Line(23) = {7, 8};   // end wall above the water
  Line(24) = {8, 4};   // top
  Curve Loop(3) = {20, 21, 22, -2};
  Plane Surface(3) = {3};
  Curve Loop(4) = {-22, 23, 24, -5};
  Plane Surface(4) = {4};
  Physical Surface("water") = {1, 3};
  Physical Surface("air") = {2, 4};
  Physical Curve("bed") = {1, 20};
  Physical Curve("ends") = {4, 7, 21, 23};
  Physical Curve("top") = {6, 24};
Else
  Physical Surface("water") = {1};
  Physical Surface("air") = {2};
  Physical Curve("bed") = {1};
  Physical Curve("ends") = {2, 4, 5, 7};
  Physical Curve("top") = {6};
EndIf
