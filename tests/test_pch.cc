// The one source of massprops_test_pch (tests/CMakeLists.txt), the target that builds the test
// files' precompiled header; it has nothing of its own to compile.
