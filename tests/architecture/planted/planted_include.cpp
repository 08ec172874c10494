// Compiled by tests/architecture/planted_includes.cmake with one stage target's include
// directories and -DPLANTED_HEADER=<folder/header.h>: a header of a later stage must not be
// found (docs/integration.md "Layering"); one of the stage's own or an earlier stage's must.
#define SHADOWC_PLANTED_STR(x) #x
#define SHADOWC_PLANTED_XSTR(x) SHADOWC_PLANTED_STR(x)
#include SHADOWC_PLANTED_XSTR(PLANTED_HEADER)

int main() { return 0; }
