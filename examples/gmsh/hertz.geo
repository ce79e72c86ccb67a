// Hertz contact, 2D plane strain: the lower half of an elastic cylinder of radius R = 1 (centre
// (0, 1)), its flat top clamped, pushed down onto a rigid plane by delta (the plane's surface at
// y = delta, the cylinder touching y = 0 at first). Triangles (P1), 0.004 long near the contact,
// 0.08 away from it. Make hertz.msh with:
//   gmsh -2 hertz.geo -format msh41 -o hertz.msh
// the quadratic (P2) version with -order 2 -o hertz_p2.msh, and the coarser meshes of the
// refinement test (every size 4 and 2 times larger) with -clscale 4 -o hertz_coarse.msh and
// -clscale 2 -o hertz_medium.msh.
R = 1.0;
h_far = 0.08;
h_contact = 0.004;
Point(1) = {0, 1, 0, h_far};      // centre
Point(2) = {-R, 1, 0, h_far};
Point(3) = {0, 0, 0, h_contact};  // the first point of contact
Point(4) = {R, 1, 0, h_far};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
// Small cells within 0.25 of the contact point, growing to h_far by 0.6.
Field[1] = Distance;
Field[1].PointsList = {3};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.12;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Physical Curve("arc") = {1, 2};
Physical Curve("top") = {3};
Physical Surface("cylinder") = {1};
