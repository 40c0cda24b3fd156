# Geometry tests (see host/scene/geometry.c): fluid fill, USAW vertices and segments, dummy layers,
# inflow/outflow layers and input errors, on scenes built in C (no Lua, no OpenCL).
clsph_test_exe(test_geometry unit/test_geometry.c)
clsph_add_test(geometry COMMAND test_geometry LABELS unit)
# STL surfaces (host/scene/mesh.c): loading, placing, the checks, the inside test, the nearest point
clsph_test_exe(test_mesh unit/test_mesh.c)
clsph_add_test(mesh COMMAND test_mesh LABELS unit)
