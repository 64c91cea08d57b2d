/* `octoprox check --self`: the robot against itself (self_collision.h). */
#ifndef OPX_TOOLS_CHECK_SELF_H
#define OPX_TOOLS_CHECK_SELF_H

#include "check_report.h"

/* Self-collision of the robot at its configuration (every contact's pair
 * of links listed), and with --distance the self-distance; printed as
 * text or JSON.  *collided gets 1 when two links of a checked pair touch.
 * -1 when done, else an exit code. */
int check_self(const check_context *c, int *collided);

#endif /* OPX_TOOLS_CHECK_SELF_H */
