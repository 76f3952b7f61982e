/* app.h - the sub-commands of `lamina`. Each returns the exit status. */
#ifndef LAMINA_APP_H
#define LAMINA_APP_H

#include <stdio.h>

/* wait_policy.c: before anything else, `lamina` starts itself again with
 * OpenMP threads that spin briefly and then sleep when they wait (issue 17
 * item 2); returns only when it does not. */
void app_wait_policy(char **argv);
int cmd_run(int argc, char **argv);
/* help.c: the commands' help, from one table. */
void app_usage(FILE *out);
int app_command_help(FILE *out, const char *cmd, const char *sub);
int app_wants_help(int argc, char **argv);
int cmd_diff(int argc, char **argv);
int cmd_gallery(int argc, char **argv);
int cmd_repl(int argc, char **argv);    /* the workbench, docs/workbench.md */
int cmd_watch(int argc, char **argv);
int cmd_sweep(int argc, char **argv);
int cmd_serve(int argc, char **argv);   /* the workbench in a browser */

/* issue 5: renderer benchmarks and animations of a run's frames */
int cmd_bench(int argc, char **argv);
int cmd_animate(int argc, char **argv);

#endif
