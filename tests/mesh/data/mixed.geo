// Test mesh for the Gmsh reader: a 2 x 1 rectangle, quadrilaterals on the left half and triangles
// on the right, second order (9-node quadrilaterals and 6-node triangles), with the four sides and
// the two halves as physical groups. Written in the four formats by
//   for f in msh22 msh41; do gmsh -2 -order 2 mixed.geo -format $f -o mixed_$f.msh;
//     gmsh -2 -order 2 mixed.geo -format $f -bin -o mixed_${f}_bin.msh; done
h = 0.25;
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {2, 0, 0, h};
Point(4) = {2, 1, 0, h}; Point(5) = {1, 1, 0, h}; Point(6) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
Transfinite Curve{1, 7, 5, 6} = 5; Transfinite Surface{1}; Recombine Surface{1};
Physical Curve("bottom") = {1, 2}; Physical Curve("right") = {3}; Physical Curve("top") = {4, 5};
Physical Curve("left") = {6};
Physical Surface("quads") = {1}; Physical Surface("triangles") = {2};
