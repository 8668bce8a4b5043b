/* libFuzzer entry for the gradebook target (see tests/support/fuzz_targets.h). */
#include <stddef.h>
#include <stdint.h>

#include "fuzz_targets.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sw_fuzz_gradebook(data, size);
    return 0;
}
