/* The 5x7 glyphs of canvas_text: 7 rows of 5 bits (bit 4 = left column). */
#ifndef OPX_EXAMPLES_FONT5X7_H
#define OPX_EXAMPLES_FONT5X7_H

#include <stdint.h>

/* The glyph of c (lower case as upper case); unknown characters give a
 * filled box. */
const uint8_t *font5x7_glyph(char c);

#endif /* OPX_EXAMPLES_FONT5X7_H */
