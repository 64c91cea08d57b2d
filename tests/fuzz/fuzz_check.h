/*
 * What every fuzz target checks besides "no crash, no sanitizer report":
 * each call returns a known status, never OPX_ERROR_INTERNAL (a bug by the
 * library's own definition), and a failed call leaves a message that starts
 * with the function's name.  A broken rule aborts, which libFuzzer records
 * as a finding with its input.
 */
#ifndef OPX_FUZZ_CHECK_H
#define OPX_FUZZ_CHECK_H

#include "fuzz_require.h"

#include <octoprox/octoprox.h>

#include <stdio.h>
#include <string.h>

/* Checks the status of a call to `function`; returns it. */
static inline opx_status fuzz_status(const char *function, opx_status status) {
    char detail[512];
    if (status == OPX_OK) return status;
    const char *message = opx_last_error();
    snprintf(detail, sizeof detail, "%s returned %d, last error \"%s\"", function, (int)status,
             message != NULL ? message : "(null)");
    if (status < OPX_ERROR_INTERNAL || status > OPX_OK)
        fuzz_fail(__FILE__, __LINE__, "unknown status", detail);
    if (status == OPX_ERROR_INTERNAL)
        fuzz_fail(__FILE__, __LINE__, "OPX_ERROR_INTERNAL", detail);
    if (strcmp(opx_status_name(status), "OPX_UNKNOWN_STATUS") == 0)
        fuzz_fail(__FILE__, __LINE__, "status without a name", detail);
    if (message == NULL || message[0] == '\0')
        fuzz_fail(__FILE__, __LINE__, "error without a message", detail);
    const size_t name_length = strlen(function);
    if (strncmp(message, function, name_length) != 0 || message[name_length] != ':')
        fuzz_fail(__FILE__, __LINE__, "message does not start with the function's name", detail);
    return status;
}

/* Calls a function returning opx_status and checks it; FUZZ_CALL(f, args). */
#define FUZZ_CALL(function, ...) fuzz_status(#function, function(__VA_ARGS__))

#endif /* OPX_FUZZ_CHECK_H */
