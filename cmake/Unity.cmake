# Unity builds: a library's sources compiled in batches of eight, so that the headers every source includes (fmt,
# the standard library, HDF5, the model) are parsed once a batch, not once a file. Clean builds take a third of
# the time, which is most of CI's (three builds on two cores). A batch is one translation unit: names local to a
# file (anonymous namespaces, static functions) must differ between the files of a library. A source compiled
# with its own options (contact/closest_point.cpp) stays on its own; CMake leaves such files out of batches.
# Floating-point results do not change: every file is compiled with the same options, and ISO C++ mode
# (CMAKE_CXX_EXTENSIONS OFF) keeps -ffp-contract=off whatever the compiler inlines.
function(crumple_unity_build target)
  if(CRUMPLE_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
