// The owner of the test executables' precompiled headers (tests/CMakeLists.txt,
// catena_test_pch): CMake compiles the headers listed there once, for this translation
// unit, and every test executable reuses them. It has no code of its own.
