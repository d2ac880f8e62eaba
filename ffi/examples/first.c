/* The C library in a dozen lines: draw records of the seeded bounded sample-test stream, run
 * the model on each, print coverage and depth; then the same triangle through the typed API.
 * Build and run (docs/rtl.md):
 *   cargo build --release -p uvt-ffi
 *   cc -O2 -Iffi/include ffi/examples/first.c target/release/libuvt_ffi.a -lpthread -ldl -lm -o /tmp/first
 *   /tmp/first */
#include <stdio.h>
#include "uvt.h"

int main(void) {
    uint32_t in[UVT_BSAMPLE_IN_WORDS], out[UVT_BSAMPLE_OUT_WORDS];
    for (uint64_t i = 0; i < 4; i++) {
        int n = uvt_gen(UVT_KIND_BSAMPLE, "bounded-16-16-16-20", 1, i, 16, in, UVT_BSAMPLE_IN_WORDS);
        if (n < 0 || uvt_bsample(in, out) != UVT_OK) {
            fprintf(stderr, "refused: %s\n", uvt_last_error());
            return 1;
        }
        printf("record %llu: covered %u depth 0x%08x\n", (unsigned long long)i, out[0] & 1, out[1]);
    }
    UvtTri *t = NULL;
    if (uvt_tri_new((const int32_t *)in, in[30] & 0xffff, in[30] >> 16, NULL, &t) != UVT_OK) {
        fprintf(stderr, "refused: %s\n", uvt_last_error());
        return 1;
    }
    UvtHit h;
    int r = uvt_tri_sample(t, in[32], in[33], (int32_t)in[34], (int32_t)in[35], (int32_t)in[36], &h);
    printf("typed: %d covered %d depth 0x%08x (record: %u 0x%08x)\n", r, h.covered, (uint32_t)h.depth, out[0] & 1, out[1]);
    uvt_tri_free(t);
    /* an invalid record: the error names the field */
    in[31] ^= 1;
    int code = uvt_bsample(in, out);
    printf("flipped class: %d (%s): %s\n", code, uvt_strerror(code), uvt_last_error());
    return 0;
}
