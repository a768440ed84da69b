// The object the tests' precompiled header is built with (tests/CMakeLists.txt): the header is
// GoogleTest's and the standard library's, parsed once and reused by every test executable.
