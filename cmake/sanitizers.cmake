# PLYFORM_SANITIZE=ON builds every target with AddressSanitizer and UBSan; the test suite
# must pass under it (scripts/test.sh runs it).
if(PLYFORM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# The invariant checks of core/invariant.hpp: in the sanitizer build and in Debug builds.
if(PLYFORM_SANITIZE OR CMAKE_BUILD_TYPE STREQUAL "Debug")
  add_compile_definitions(PLYFORM_CHECK_INVARIANTS)
endif()
