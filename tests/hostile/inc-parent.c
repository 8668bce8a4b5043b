/* Handing in work from outside the submissions directory at compile time:
 * ../outside/solution.c is another class's correct plugin. It must never
 * pass. */
#include "../outside/solution.c"
