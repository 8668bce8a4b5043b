/* `stepwise lesson --check FILE...`: the lesson linter teachers run before
 * sharing a lesson. Prints "FILE: ok (N pages)" on stdout for each good file
 * and the parser's "FILE:LINE:COL: ..." line on stderr for each bad one. */
#ifndef SW_CLI_LESSON_CHECK_H
#define SW_CLI_LESSON_CHECK_H

/* Check each file (a directory: every *.lesson in it, in name order).
 * Returns 0 when all pass, 2 when any fails or no file was given. */
int sw_cmd_lesson_check(int nfiles, char **files);

#endif
