// The domain of data/tee.poly for Gmsh: the T profile extruded along z over [0,20].
Point(1) = {-1, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 4.5, 0};
Point(4) = {3, 10, 0};
Point(5) = {-3, 10, 0};
Point(6) = {-1, 4.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Extrude {0, 0, 20} { Surface{1}; }
Mesh.CharacteristicLengthMax = 2;
