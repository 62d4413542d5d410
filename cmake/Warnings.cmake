# Strict warnings apply to project targets only (crumple_warnings), never to dependencies.
add_library(crumple_warnings INTERFACE)
target_compile_options(crumple_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Woverloaded-virtual -Wnull-dereference -Wimplicit-fallthrough)
if(CRUMPLE_WERROR)
  target_compile_options(crumple_warnings INTERFACE -Werror)
endif()
if(CRUMPLE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

if(CRUMPLE_NATIVE)
  add_compile_options(-march=native)
endif()
