/* fuzz_target.h - libFuzzer's entry point, declared for every target so
 * that the build's -Wmissing-prototypes holds for them too (libFuzzer
 * calls it; nothing in lamina does). */
#ifndef LAMINA_FUZZ_TARGET_H
#define LAMINA_FUZZ_TARGET_H

#include <stddef.h>
#include <stdint.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif
