// Hertz contact in 3D: a quarter of the lower half of an elastic ball of radius R = 1 (centre
// (0, 0, 1)), its flat top pushed down by a prescribed displacement onto a rigid plane z = 0 that
// the ball touches at the origin at first. The quarter x >= 0, y >= 0 is held on its symmetry
// planes by rollers (boundary parts xsym and ysym); the curved surface is the contact boundary
// (contact). Tetrahedra 0.004 long within 0.06 of the first point of contact, growing to 0.15 by
// 0.6 away. Make hertz_sphere.msh (P1) with:
//   gmsh -3 hertz_sphere.geo -format msh41 -bin -o hertz_sphere.msh
// and a coarser one (every size doubled) with -clscale 2 -o hertz_sphere_coarse.msh.
SetFactory("OpenCASCADE");
R = 1.0;
h_contact = 0.004;
h_far = 0.15;
Sphere(1) = {0, 0, R, R, -Pi/2, 0, Pi/2};
Box(2) = {0, 0, 0, R, R, R};
BooleanIntersection(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
eps = 1e-6;
top() = Surface In BoundingBox{-eps, -eps, R - eps, R + eps, R + eps, R + eps};
xsym() = Surface In BoundingBox{-eps, -eps, -eps, eps, R + eps, R + eps};
ysym() = Surface In BoundingBox{-eps, -eps, -eps, R + eps, eps, R + eps};
curved() = Boundary{ Volume{3}; };
curved() -= top();
curved() -= xsym();
curved() -= ysym();
Physical Surface("top") = top();
Physical Surface("xsym") = xsym();
Physical Surface("ysym") = ysym();
Physical Surface("contact") = curved();
Physical Volume("ball") = {3};
pole() = Point In BoundingBox{-eps, -eps, -eps, eps, eps, eps};
Field[1] = Distance;
Field[1].PointsList = {pole()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 0.06;
Field[2].DistMax = 0.6;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
