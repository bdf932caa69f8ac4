// The same check as header_check.c, compiled as C++11 (-Wall -Wextra -pedantic -Werror).
#include "header_check.c"
