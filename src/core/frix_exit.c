/* Ends the program with a status and no "STOP"/"ERROR STOP" banner: the program's main
 * prints its own message first. libgfortran flushes its units in its exit handler. */
#include <stdlib.h>
void frix_exit_c(int status) { exit(status); }
