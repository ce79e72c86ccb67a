// The paper's body, Omega = (0,3) x (0,1), as Gmsh makes it: 60 x 20 bilinear quadrilaterals
// (a transfinite, recombined surface), the same mesh as [mesh] type = "rectangle" with nx = 60,
// ny = 20. The four sides are physical curves named as the rectangle names them, the body a
// physical surface. Make paper.msh with:  gmsh -2 paper.geo -format msh41 -o paper.msh
Point(1) = {0, 0, 0}; Point(2) = {3, 0, 0}; Point(3) = {3, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 61;
Transfinite Curve{2, 4} = 21;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("body") = {1};
