// print the doc-table estimates for the test's cases
#define main unused_main
#include "/work/main/test/skeleton/test_estimate_rips_radius.cpp"
#undef main
