/* cmd_repl.c - `lamina repl [SCRIPT.lua] [--set name=value ...] [--quiet]`:
 * a Lua prompt over a live simulation (docs/workbench.md).
 *
 * The script runs up to its first sim:run (or its lamina.pause(); see
 * l_pause.c), then every line typed runs in the same Lua state: step, run,
 * change materials, draw frames, inspect. Ctrl-C stops a run at its next
 * step boundary and comes back to the prompt; Ctrl-D (end of input) ends
 * the session. Exit status 0, or 2 for a command-line mistake or a script
 * that cannot be loaded. */
#include <lua.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "render.h"
#include "workbench.h"

static const char usage_line[] = "usage: lamina repl [SCRIPT.lua] [--set name=value ...] [--quiet]";

static int parse_args(int argc, char **argv, lamina_run *run)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v;
        int got = wb_option("repl", argc, argv, &i, "--set", &v);
        if (got < 0) return -1;
        if (got) {
            if (wb_add_set("repl", run, v)) return -1;
        } else if (wb_word("repl", a, &run->quiet, &run->script, usage_line)) {
            return -1;
        }
    }
    return 0;
}

/* "exit" or "quit" alone ends the session, as people type them. */
static int is_quit(const char *line)
{
    while (*line == ' ' || *line == '\t') line++;
    size_t n = strcspn(line, " \t");
    const char *rest = line + n;
    while (*rest == ' ' || *rest == '\t') rest++;
    return !*rest && ((n == 4 && strncmp(line, "exit", 4) == 0) ||
                      (n == 4 && strncmp(line, "quit", 4) == 0));
}

/* Reads, compiles (asking for more lines while a statement is open) and
 * runs entries until the end of input. */
static void prompt_loop(lua_State *L, lamina_run *run, repl_input *in)
{
    for (;;) {
        char *code = repl_input_read(in, "> ");
        if (!code) break;
        if (is_quit(code)) {
            free(code);
            break;
        }
        int rc;
        while ((rc = repl_compile(L, code)) == REPL_INCOMPLETE) {
            char *more = repl_input_read(in, ">> ");
            if (!more) break;
            size_t n = strlen(code), m = strlen(more);
            char *joined = realloc(code, n + m + 2);
            if (!joined) {
                free(more);
                break;
            }
            code = joined;
            code[n] = '\n';
            memcpy(code + n + 1, more, m + 1);
            free(more);
        }
        if (rc == REPL_INCOMPLETE) rc = repl_compile(L, code);   /* report the error */
        repl_input_remember(in, code);
        free(code);
        lamina_interrupt_clear();   /* a Ctrl-C typed at the prompt is spent */
        if (rc == REPL_OK) {
            repl_call(L, run);
        } else {
            fprintf(stderr, "%s\n", lua_tostring(L, -1));
            lua_pop(L, 1);
        }
    }
    if (in->tty && !in->readline) fputc('\n', stdout);
}

/* A --set the script has not read yet may be read at the prompt: a note,
 * not an error. */
static void note_unused_sets(const lamina_run *run)
{
    for (int i = 0; i < run->nsets; i++)
        if (!run->sets[i].used)
            fprintf(stderr, "lamina repl: note: --set %s: the script has not read it "
                    "(lamina.param('%s', ...))\n", run->sets[i].name, run->sets[i].name);
}

int cmd_repl(int argc, char **argv)
{
    lamina_run run;
    memset(&run, 0, sizeof run);
    run.sets = calloc((size_t)argc + 1, sizeof *run.sets);
    if (!run.sets) return LAMINA_EXIT_USAGE;
    if (parse_args(argc, argv, &run)) {
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    if (run.script) {
        wb_file_sig sig;
        wb_file_sig_read(run.script, &sig);
        if (!sig.ok) {
            perror(run.script);
            fprintf(stderr, "lamina repl: cannot read script '%s'\n", run.script);
            wb_free_sets(&run);
            return LAMINA_EXIT_USAGE;
        }
        snprintf(run.script_hash, sizeof run.script_hash, "%016llx",
                 (unsigned long long)sig.hash);
    }
    lua_State *L = lamina_open_state(&run);
    if (!L) {
        fprintf(stderr, "lamina repl: cannot create a Lua state (out of memory)\n");
        wb_free_sets(&run);
        return LAMINA_EXIT_USAGE;
    }
    setvbuf(stdout, NULL, _IOLBF, 0);   /* a program reading the pipe sees each line */
    lamina_interrupt_install(L);
    int status = LAMINA_EXIT_OK;
    if (run.script && lamina_script_start(L, &run) == LAMINA_SCRIPT_BAD) {
        status = LAMINA_EXIT_USAGE;
    } else {
        if (run.script) note_unused_sets(&run);
        repl_input in;
        repl_input_open(&in);
        if (in.tty)
            fprintf(stderr, "lamina %s repl: Lua 5.4 over the simulation; Ctrl-C stops a "
                    "run, Ctrl-D ends (docs/workbench.md)\n", LAMINA_VERSION);
        prompt_loop(L, &run, &in);
        repl_input_close(&in);
    }
    lamina_interrupt_uninstall();
    lua_close(L);
    wb_free_sets(&run);
    lr_shutdown();
    return status;
}
