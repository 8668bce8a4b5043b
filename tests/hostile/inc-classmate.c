/* Handing in a classmate's work at compile time: the whole submission is
 * one #include of bob.c, an honest classmate's plugin in the same
 * directory (the compiler looks beside the file first). Compiled where
 * only this submission exists, it does not build; it must never pass. */
#include "bob.c"
