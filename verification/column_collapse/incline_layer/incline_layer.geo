// A 0.2 m layer of the column's sand on a no-slip incline at theta (known-failure-full.md):
// the domain is rotated by the slope angle, gravity stays vertical. Change theta and hl here.
theta = 35 * Pi / 180;  Ls = 6.0;  Hd = 0.5;  x0 = 1.0;  Ll = 2.0;  hl = 0.2;
c = Cos(theta);  s = Sin(theta);
// rotate (u, v) -> (u c + v s, -u s + v c): the slope descends towards +x
Point(1) = {0, 0, 0};
Point(2) = {x0*c, -x0*s, 0};
Point(3) = {(x0+Ll)*c, -(x0+Ll)*s, 0};
Point(4) = {Ls*c, -Ls*s, 0};
Point(5) = {Ls*c + Hd*s, -Ls*s + Hd*c, 0};
Point(6) = {Hd*s, Hd*c, 0};
Point(7) = {(x0+Ll)*c + hl*s, -(x0+Ll)*s + hl*c, 0};
Point(8) = {x0*c + hl*s, -x0*s + hl*c, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {3, 7}; Line(8) = {7, 8}; Line(9) = {8, 2};
Curve Loop(1) = {2, 7, 8, 9}; Plane Surface(1) = {1};
Curve Loop(2) = {1, -9, -8, -7, 3, 4, 5, 6}; Plane Surface(2) = {2};
Physical Surface("layer") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1, 2, 3};
Physical Curve("ends") = {4, 6};
Physical Curve("top") = {5};
