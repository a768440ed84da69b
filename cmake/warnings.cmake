# Warnings as the project requires them: clean under -Wall -Wextra.
add_library(plyform_warnings INTERFACE)
target_compile_options(plyform_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX,C>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<COMPILE_LANGUAGE:Fortran>:-Wall -Wextra>)
