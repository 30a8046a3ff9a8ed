// The Hertz impact benchmark's sphere (tests/bench/hertz_scene.c): radius R about the origin,
// meshed finest at its south pole (0, 0, -R), the point that meets the plane. Element size
// lc_min within d_min of the pole, growing linearly to lc_max at d_max and beyond. order 2
// gives 10-node tets (Gmsh type 11) whose boundary mid-edge nodes lie on the sphere.
// make_hertz_meshes.sh runs it for each committed mesh.
SetFactory("OpenCASCADE");
DefineConstant[ R = 0.05, lc_min = 0.001, lc_max = 0.01, d_min = 0.002, d_max = 0.03, order = 1 ];
Sphere(1) = {0, 0, 0, R};
Point(100) = {0, 0, -R};
Field[1] = Distance;
Field[1].PointsList = {100};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = lc_min;
Field[2].SizeMax = lc_max;
Field[2].DistMin = d_min;
Field[2].DistMax = d_max;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.ElementOrder = order;
Mesh.Optimize = 1;
