/* The header-only contact example built as C++17: same program, same numbers. */
#include "header_only_contact.c"
