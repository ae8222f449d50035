// Case A of Zhao et al. (2023), section 3.1, in 3D: the 2D scene of ../case_a_2d/case_a.geo
// extruded one cell (0.01 m) in z and meshed with tetrahedra, as the paper's Anura3D model
// (a 3D mesh one cell thick). Real coordinates: x horizontal, y up, z across the flume;
// gravity along -y. Every point is O + s d + t n in slope coordinates (s along the slope,
// downhill; t normal to it), see case_a.geo for the sketch.

slope = 22 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);  // d: along the slope, downhill
nx = Sin(slope);  ny = Cos(slope);   // n: normal to the slope, out of the bed

length = 2.0;               // modelled slope length
layer = 0.0046;             // erodible layer thickness
column_length = 0.2;        // granular column behind the gate
column_top = layer + 0.14;  // the 0.14 m high column stands on the layer
band_top = 0.25;            // top of the modelled band
thickness = 0.01;           // one cell across (z)

Point(1) = {0 * dx + 0 * nx, 0 * dy + 0 * ny, 0};
Point(2) = {length * dx + 0 * nx, length * dy + 0 * ny, 0};
Point(3) = {length * dx + layer * nx, length * dy + layer * ny, 0};
Point(4) = {column_length * dx + layer * nx, column_length * dy + layer * ny, 0};
Point(5) = {0 * dx + layer * nx, 0 * dy + layer * ny, 0};
Point(6) = {column_length * dx + column_top * nx, column_length * dy + column_top * ny, 0};
Point(7) = {0 * dx + column_top * nx, 0 * dy + column_top * ny, 0};
Point(8) = {0 * dx + band_top * nx, 0 * dy + band_top * ny, 0};
Point(9) = {length * dx + band_top * nx, length * dy + band_top * ny, 0};

Line(1) = {1, 2};    // bed
Line(2) = {2, 3};    // end, beside the layer
Line(3) = {3, 4};    // layer surface downstream of the gate
Line(4) = {4, 5};    // layer surface under the column
Line(5) = {5, 1};    // wall, beside the layer
Line(6) = {4, 6};    // gate
Line(7) = {6, 7};    // column top
Line(8) = {7, 5};    // wall, beside the column
Line(9) = {7, 8};    // wall, above the column
Line(10) = {8, 9};   // top
Line(11) = {9, 3};   // end, above the layer

Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};                    // erodible layer
Curve Loop(2) = {-4, 6, 7, 8};
Plane Surface(2) = {2};                    // column
Curve Loop(3) = {-3, -11, -10, -9, -7, -6};
Plane Surface(3) = {3};                    // air

// One extrusion of all three surfaces, so the faces they share (layer surface, gate, column
// top) are extruded once and the volumes' meshes conform. Without Recombine, each layer of
// prisms is split into tetrahedra. For each surface the result lists the far (z = thickness)
// surface, the volume, then the side surfaces of its curves in curve-loop order:
//   ex[0..6]   layer:  top, volume, curves 1, 2, 3, 4, 5
//   ex[7..12]  column: top, volume, curves 4, 6, 7, 8
//   ex[13..20] air:    top, volume, curves 3, 11, 10, 9, 7, 6
ex[] = Extrude {0, 0, thickness} { Surface{1, 2, 3}; Layers{1}; };

Physical Volume("layer") = {ex[1]};
Physical Volume("column") = {ex[8]};
Physical Volume("air") = {ex[14]};
Physical Surface("bed") = {ex[2]};
Physical Surface("wall") = {ex[6], ex[12], ex[18]};
Physical Surface("gate") = {ex[10]};
Physical Surface("end") = {ex[3], ex[16]};
Physical Surface("top") = {ex[17]};
Physical Surface("sides") = {1, 2, 3, ex[0], ex[7], ex[13]};
