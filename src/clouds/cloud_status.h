/* What the cloud readers return: 0, or why they failed (all negative). */
#ifndef OPX_CLOUDS_CLOUD_STATUS_H
#define OPX_CLOUDS_CLOUD_STATUS_H

#define CLOUD_ERROR_CORRUPT (-1)     /* malformed or truncated data */
#define CLOUD_ERROR_IO (-2)          /* the file cannot be opened */
#define CLOUD_ERROR_NO_MEMORY (-3)   /* too little memory for the points */
#define CLOUD_ERROR_UNSUPPORTED (-4) /* valid, but a layout the readers do not take */
#define CLOUD_ERROR_INVALID (-5)     /* a NULL path or output */

#endif /* OPX_CLOUDS_CLOUD_STATUS_H */
