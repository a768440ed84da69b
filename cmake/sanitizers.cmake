# PLYFORM_SANITIZE=ON builds every target with AddressSanitizer and UBSan; the test suite
# must pass under it (scripts/test.sh runs it).
if(PLYFORM_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()
