# Snapshot and checkpoint tests (see io.c). The test writes its files under
# ${CMAKE_CURRENT_BINARY_DIR}/io-test. It also runs xmllint (libxml2-utils), h5dump (hdf5-tools)
# and ParaView's XDMF3 reader through pvpython and io/pv_check.py (python3-paraview) on its files
# when they are installed, and prints a note for each that is not.
clsph_test_exe(test_io cl/test_io.c)
clsph_add_test(io COMMAND test_io ${CMAKE_CURRENT_BINARY_DIR}
               ${CMAKE_CURRENT_SOURCE_DIR}/io/pv_check.py LABELS cl)
