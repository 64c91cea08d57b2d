/*
 * With --json a command prints one JSON object, whole or not at all: its
 * report is held in a temporary file until the command ends.  On success
 * (exit 0 or 1) the held report goes to stdout; on failure it is dropped
 * and one error object takes its place:
 *   {"error": {"command": "check", "exit_code": 3, "status": "input_error",
 *              "library_status": "OPX_ERROR_CORRUPT", "message": "..."}}
 * (library_status null when no library call failed).
 */
#ifndef OPX_TOOLS_HELD_REPORT_H
#define OPX_TOOLS_HELD_REPORT_H

/* 1 when an argument is exactly --json. */
int held_report_wanted(int argc, char **argv);

/* Sends stdout to a temporary file from here on.  Without a temporary
 * file (no writable /tmp) the report goes out as it is written. */
void held_report_begin(void);

/* Ends the hold: prints the held report or, after a failure, the error
 * object for `command` (NULL: none was recognised); returns the exit
 * code (3 when the held report could not be written whole). */
int held_report_end(const char *command, int code);

#endif /* OPX_TOOLS_HELD_REPORT_H */
