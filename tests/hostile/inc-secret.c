/* Reading the teacher's home at compile time: @HOME@/reference.h is the
 * teacher's reference solution (with a secret marker, SWSECRET...). With
 * it the submission is correct, so it passes today; it must not, and the
 * marker must not appear in the gradebook. */
#include "@HOME@/reference.h"
