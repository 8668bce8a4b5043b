/* Reading a system file at compile time: the compiler's first error quotes
 * what it read. It must not pass, and nothing of /etc/passwd
 * ("root:x:0:") may reach the gradebook or the teacher's terminal. */
#include "/etc/passwd"
