/* The header-only example built as C++17: same program, same numbers. */
#include "header_only.c"
