// The translation unit that builds the test suites' precompiled header
// (host_tests/CMakeLists.txt, sinu_test_pch); it has no code of its own.
