/* The contact test compiled as C++17: the header must give the same bits from a C++ compiler. */
#include "test_inline_contact.c"
