// A disc of radius 1 pressed between two rigid planes, by symmetry a quarter of it: x >= 0,
// y >= 0, with rollers on the two cut lines (physical curves "axis_x", y = 0, and "axis_y",
// x = 0) and the arc (physical curve "arc") in possible contact with the upper plane.
// Quadrilaterals of second order (Q2, 9 nodes), 0.01 long near the contact point (0, 1), 0.1 away
// from it. Make disc_quarter.msh with:
//   gmsh -2 disc_quarter.geo -format msh41 -o disc_quarter.msh
h_far = 0.1;
h_contact = 0.01;
Point(1) = {0, 0, 0, h_far};
Point(2) = {1, 0, 0, h_far};
Point(3) = {0, 1, 0, h_contact};
Line(1) = {1, 2};
Circle(2) = {2, 1, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Field[1] = Distance;
Field[1].PointsList = {3};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.15;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Recombine Surface{1};
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 0;
Physical Curve("axis_x") = {1};
Physical Curve("arc") = {2};
Physical Curve("axis_y") = {3};
Physical Surface("disc") = {1};
