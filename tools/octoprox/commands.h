/* The subcommands of the octoprox tool; each returns an exit code. */
#ifndef OPX_TOOLS_COMMANDS_H
#define OPX_TOOLS_COMMANDS_H

/* argv[0] is the subcommand's name. */
int cmd_info(int argc, char **argv);
int cmd_ingest(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_export(int argc, char **argv);

#endif /* OPX_TOOLS_COMMANDS_H */
