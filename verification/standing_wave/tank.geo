// Standing wave verification tank (README.md): water h = 0.15 m deep between walls at x = 0
// and x = L = 0.5 m, its surface displaced into the first sloshing mode,
// eta0(x) = a cos(pi x / L), a = 0.01 m, and released from rest. "air" is empty mesh above the
// water for the surface to rise into.
//
//  y = top  +-----------------------------------+
//           |  air                              |
//  y = h+a  *-._                                |
//  y = h    |    `-._                           |
//           |        `-._                   _.-*  y = h - a
//           |  water                            |
//  y = 0    +--------------- bed ---------------+
//          x = 0                              x = L

h = 0.15;    // still water depth (Case B's)
a = 0.01;    // amplitude of the mode at the walls
L = 0.5;     // tank length: the mode's wavelength is 2 L
top = 0.25;  // top of the mesh
n = 50;      // points of the spline along the cosine (a chord between two would miss it by a (pi / n)^2 / 8 < 0.02 mm)

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(4) = {L, top, 0};
Point(5) = {0, top, 0};
For i In {0:n}
  x = L * (n - i) / n;  // from the end wall x = L (i = 0) to the wall x = 0 (i = n)
  Point(10 + i) = {x, h + a * Cos(Pi * x / L), 0};
EndFor

Line(1) = {1, 2};        // bed
Line(2) = {2, 10};       // end wall beside the water
Line(4) = {10 + n, 1};   // wall x = 0 beside the water
Line(5) = {10, 4};       // end wall above the water
Line(6) = {4, 5};        // top
Line(7) = {5, 10 + n};   // wall x = 0 above the water
// The surface is one spline through the points, so the mesher places its nodes at the
// scene's cell size (50 straight lines would each be a mesh edge, cells of L / 50 along the
// surface whatever cell_size says).
Spline(100) = {10 : 10 + n};

Curve Loop(1) = {1, 2, 100, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -100};
Plane Surface(2) = {2};

Physical Surface("water") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1};
Physical Curve("walls") = {2, 4, 5, 7};
Physical Curve("top") = {6};
