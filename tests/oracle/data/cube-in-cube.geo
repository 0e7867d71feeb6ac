// The domain of data/cube-in-cube.poly for Gmsh: the cube [0,10]^3 minus the void [4,6]^3.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 10, 10, 10};
Box(2) = {4, 4, 4, 2, 2, 2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = 2;
