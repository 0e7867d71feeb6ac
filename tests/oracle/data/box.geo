// The domain of data/box.poly for Gmsh: the box [0,3] x [0,2] x [0,1].
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 3, 2, 1};
Mesh.CharacteristicLengthMax = 0.5;
