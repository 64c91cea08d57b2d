/* The demo's story on the shared real data (--real): the RGB-D frame of
 * rgbd/ and the PR2 of robots/pr2_description/; then the PR2's right arm
 * in its head camera's frame, ingested without and with self-filtering
 * (demo_self_filter.h). */
#ifndef OPX_EXAMPLES_DEMO_REAL_H
#define OPX_EXAMPLES_DEMO_REAL_H

/* 0 on success; -1 after a message (2 when the data is missing). */
int demo_real_run(const char *data_dir, const char *out_dir, int quick);

#endif /* OPX_EXAMPLES_DEMO_REAL_H */
