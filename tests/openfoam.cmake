# OpenFOAM references of the k-epsilon channels (tests/validation/openfoam/channel_ke, Wang, Sun &
# Hu sec 5.1-5.3): each test re-runs one case of run.sh into the build tree and compares the fresh
# CSV with tests/data/openfoam_channel_<case>.csv (compare.py: U to a relative 1e-3). They need
# OpenFOAM v1912 (Debian's openfoam package; skipped, exit 77, without it) and take minutes of one
# core (straight 0.5, mild 1.5, strong 1, hcd 0.5, hcd_fine 4-6): labels slow and openfoam, so CI
# (-LE slow) leaves them out; ctest -L openfoam runs them.
foreach(case straight mild strong hcd hcd_fine)
  clsph_add_test(openfoam_channel_${case} TIMEOUT 1800 LABELS "slow;openfoam"
                 COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/validation/openfoam/channel_ke/check.sh ${case}
                         ${CMAKE_CURRENT_BINARY_DIR}/openfoam_channel/${case})
endforeach()
# one OpenFOAM run at a time: each is serial, and the references were made that way
set_tests_properties(openfoam_channel_straight openfoam_channel_mild openfoam_channel_strong
                     openfoam_channel_hcd openfoam_channel_hcd_fine PROPERTIES RUN_SERIAL TRUE)
# The fish-pass reference (tests/validation/openfoam/fish_pass, Leroy et al. sec 5.2): pimpleFoam
# from rest to 20 s on two meshes, about 25 minutes of one core; the fresh profiles against
# tests/data/openfoam_fish_pass.csv (check.sh: U within 1e-2 of the peak)
clsph_add_test(openfoam_fish_pass TIMEOUT 3600 LABELS "slow;openfoam"
               COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/validation/openfoam/fish_pass/check.sh
                       ${CMAKE_CURRENT_BINARY_DIR}/openfoam_fish_pass)
set_tests_properties(openfoam_fish_pass PROPERTIES RUN_SERIAL TRUE)
