/* SPDX-License-Identifier: BSD-3-Clause */
/* Which clone the load-time dispatch of target_clones("fma", "default")
 * picks on the CPU this runs on (the mechanism of PW85_FMA_CLONES,
 * src/compiler.hpp): prints "fma" or "default". tests/test-nofma.sh checks
 * that the emulated CPU takes "default", else its comparison would prove
 * nothing. x86-64 with GCC or Clang only (tests/meson.build). */
#include <stdio.h>

__attribute__((target_clones("fma", "default"))) int probe(double x) {
  return x > 0.;
}

/* The dispatcher and the two clones, by their assembler names (GCC and
 * Clang name them so on ELF). */
extern void *probe_resolver(void) __asm__("probe.resolver");
extern int probe_fma(double) __asm__("probe.fma");
extern int probe_default(double) __asm__("probe.default");

int main(void) {
  void *const picked = probe_resolver();
  if (picked == (void *)probe_fma) {
    puts("fma");
  } else if (picked == (void *)probe_default) {
    puts("default");
  } else {
    puts("unknown");
    return 1;
  }
  return probe(1.) == 1 ? 0 : 1;
}
