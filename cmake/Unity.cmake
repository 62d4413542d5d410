# Unity builds: the sources of a library or a test program compiled in batches of sixteen, so that the headers every
# source includes (fmt, GoogleTest, the standard library, HDF5, the model) are parsed and their templates
# instantiated once a batch, not once a file. A clean release build took 3.0 minutes on two cores against 5.7
# (2026-12-05), and builds are 40 % of CI's time (three of them). On 2026-12-07 a clean release build took 292 s
# in batches of eight, 262 s in batches of sixteen and 262 s in batches of 32 (less work, but fewer batches to
# share between the two cores at the end). A batch is one translation unit: names local to a
# file (anonymous namespaces, static functions) must differ between the files of a library, and each test file
# keeps its helpers and tests in a namespace named after the file. A source compiled with its own options
# (contact/closest_point.cpp) stays on its own; CMake leaves such files out of batches.
# Floating-point results do not change: every file is compiled with the same options, and ISO C++ mode
# (CMAKE_CXX_EXTENSIONS OFF) keeps -ffp-contract=off whatever the compiler inlines.
function(crumple_unity_build target)
  if(CRUMPLE_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
  endif()
endfunction()
