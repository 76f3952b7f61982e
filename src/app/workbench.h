/* workbench.h - shared by lamina repl, watch and sweep (docs/workbench.md). */
#ifndef LAMINA_WORKBENCH_H
#define LAMINA_WORKBENCH_H

#include <stdint.h>

#include "lamina_lua.h"

/* "--name value" or "--name=value" at argv[*i]: 1 and the value in *val
 * (advancing *i), 0 when argv[*i] is not --name, -1 (message printed) when
 * the value is missing. */
int wb_option(const char *cmd, int argc, char **argv, int *i, const char *name,
              const char **val);
/* argv[*i] as one of n options whose values are kept as given (names[k]
 * into *slots[k]): as wb_option. */
int wb_options(const char *cmd, int argc, char **argv, int *i, int n,
               const char *const names[], const char **const slots[]);
/* A word of a command line that is no option's value: --quiet or -q (when
 * quiet is not NULL), an unknown option, or the script (one at most). 0,
 * or -1 with a message ending in usage, or in "(try 'lamina help')" when
 * usage is NULL. */
int wb_word(const char *cmd, const char *a, int *quiet, const char **script,
            const char *usage);
/* Adds --set name=value to run->sets (room for argc entries was allocated);
 * -1 with a message on a malformed or repeated name. */
int wb_add_set(const char *cmd, lamina_run *run, const char *kv);
void wb_free_sets(lamina_run *run);
/* A whole number in [lo, hi]; -1 with a message otherwise. */
int wb_count(const char *cmd, const char *opt, const char *s, long lo, long hi, long *out);
/* A number in [lo, hi]; -1 with a message otherwise. */
int wb_number(const char *cmd, const char *opt, const char *s, double lo, double hi,
              double *out);
/* path made absolute against the working directory (it need not exist);
 * malloc'd, NULL when out of memory. */
char *wb_absolute(const char *path);
/* Seconds on a monotonic clock. */
double wb_now(void);

/* The script's content: FNV-1a (as cmd_run.c stamps it into PNGs), size and
 * modification time; ok = 0 when it cannot be read. */
typedef struct wb_file_sig {
    int ok;
    long long size, mtime_ns;
    uint64_t hash;
} wb_file_sig;
void wb_file_sig_read(const char *path, wb_file_sig *sig);
int wb_file_sig_same(const wb_file_sig *a, const wb_file_sig *b);

/* repl_input.c: lines from a terminal (readline when built with it) or a
 * pipe. */
typedef struct repl_input {
    int tty;        /* stdin is a terminal: prompts are shown */
    int readline;   /* ...and readline edits the line */
} repl_input;
void repl_input_open(repl_input *in);
/* A line without its newline (malloc'd), "" when Ctrl-C discarded it, NULL
 * at the end of input. */
char *repl_input_read(repl_input *in, const char *prompt);
void repl_input_remember(repl_input *in, const char *entry);
void repl_input_close(repl_input *in);

/* repl_eval.c: one entry typed at the prompt. */
enum { REPL_OK, REPL_ERROR, REPL_INCOMPLETE };
/* Compiles code as "return CODE" (an expression: its values are printed)
 * or as a statement; REPL_INCOMPLETE when the statement goes on. On
 * REPL_OK the function is pushed; on REPL_ERROR the message is. */
int repl_compile(lua_State *L, const char *code);
/* Runs the function on top and prints its results (as lua.c does); errors
 * are printed and the session goes on. */
int repl_call(lua_State *L, lamina_run *run);

#endif
