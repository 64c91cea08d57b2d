/* The demo on real data: see demo_real.h.  (Filled in below.) */
#include "demo_real.h"

#include <stdio.h>

int demo_real_run(const char *data_dir, const char *out_dir, int quick) {
    (void)data_dir;
    (void)out_dir;
    (void)quick;
    fprintf(stderr, "opx-demo: --real is not written yet\n");
    return -1;
}
