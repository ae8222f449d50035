// Diagnostic variant of examples/case_a_2d/case_a.geo with the slope set to 0 (see
// verification/case_a/known-failure.md): everything else is the same scene.
// Case A of Zhao et al. (2023), section 3.1: a granular column collapsing on an erodible
// layer that covers a 22 degree slope (lab: Mangeney et al. 2010). Real coordinates: x
// horizontal, y up, gravity along -y. The slope descends towards +x from the foot O = (0, 0)
// of the upstream wall. Every point is written as O + s d + t n with the along-slope unit
// vector d and the slope normal n, so the scene stays readable in slope coordinates (s, t).
//
//   t = 0.25   +-----------------------------------------------+  top
//              |                    air                        |
//   t = 0.1446 +------+                                        |
//        wall  |column| gate                                   |  end
//   t = 0.0046 +------+----------------------------------------+
//              |                erodible layer                 |
//   t = 0      +-----------------------------------------------+  bed
//             s = 0  s = 0.2                                  s = 2
//
// The mesh size comes from the scene's cell_size (lituya pre sets Mesh.MeshSizeMax), so the
// points carry no size of their own.

slope = 0;  // diagnostic: the same column and layer on a flat bed
dx = Cos(slope);  dy = -Sin(slope);  // d: along the slope, downhill
nx = Sin(slope);  ny = Cos(slope);   // n: normal to the slope, out of the bed

length = 2.0;            // modelled slope length (the flume is 3 m; the paper models 2 m)
layer = 0.0046;          // erodible layer thickness
column_length = 0.2;     // granular column behind the gate
column_top = layer + 0.14;  // the 0.14 m high column stands on the layer
band_top = 0.25;         // top of the modelled band (air above the material)

// Point(i) = O + s d + t n
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

// Loops run counter-clockwise, so gmsh's triangles come out counter-clockwise (positive).
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};                    // erodible layer
Curve Loop(2) = {-4, 6, 7, 8};
Plane Surface(2) = {2};                    // column
Curve Loop(3) = {-3, -11, -10, -9, -7, -6};
Plane Surface(3) = {3};                    // air (L-shaped: shares the gate and column top)

Physical Surface("layer") = {1};
Physical Surface("column") = {2};
Physical Surface("air") = {3};
Physical Curve("bed") = {1};
Physical Curve("wall") = {5, 8, 9};
Physical Curve("gate") = {6};
Physical Curve("end") = {2, 11};
Physical Curve("top") = {10};
