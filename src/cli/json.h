/* JSON output for check and grade: strings always valid UTF-8 with control
 * bytes escaped, numbers in shortest round-trip form, and non-finite
 * numbers as the strings "inf", "-inf" and "nan" (JSON has no such numbers;
 * null would lose them). */
#ifndef SW_CLI_JSON_H
#define SW_CLI_JSON_H

#include <stdio.h>

/* A JSON string, or null for NULL. */
void sw_json_str(FILE *out, const char *s);
/* A number in the shortest form that reads back exactly ("1e-09", "0.02"). */
void sw_json_num(FILE *out, double v);
/* A whole number, or null when v < 0 and null_negative is set. */
void sw_json_long(FILE *out, long v, int null_negative);
/* ,\n  "key": — the separator and key of the next member at indent. */
void sw_json_key(FILE *out, int indent, const char *key, int first);

#endif
