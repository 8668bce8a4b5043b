/* Printing a check's verdict: the plain report or the JSON object
 * (docs/trace-format.md lists the fields). */
#ifndef SW_CLI_CHECK_REPORT_H
#define SW_CLI_CHECK_REPORT_H

#include "grade/verdict.h"

/* Print v (plain, or JSON) on stdout, the error line on stderr for an
 * unusable input; returns the exit status: 0, 1, or 2 (also when stdout
 * cannot be written, with a message on stderr). */
int sw_check_print(const sw_verdict *v, int json);
/* The JSON error object for an unusable input (its line is already on stderr). */
void sw_check_print_error(const char *msg);
/* The plain report on out. */
void sw_check_print_plain(FILE *out, const sw_verdict *v);

#endif
