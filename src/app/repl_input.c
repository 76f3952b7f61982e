/* repl_input.c - the lines typed at `lamina repl`'s prompt.
 *
 * On a terminal, with readline found at build time (LAMINA_HAVE_READLINE),
 * lines are edited and kept in a history (~/.lamina_history); Ctrl-C
 * discards the line being typed and shows a fresh prompt. Otherwise lines
 * are read from stdin as they come (a pipe, a file), without prompts unless
 * stdin is a terminal, so that a session can be driven by another program. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "workbench.h"

#ifdef LAMINA_HAVE_READLINE
#include <readline/history.h>
#include <readline/readline.h>

static char history_path[1024];

/* readline calls this when a read was cut by a signal (rl_catch_signals is
 * off, so SIGINT reaches lamina's handler): Ctrl-C drops the line. */
static int on_signal_event(void)
{
    if (lamina_interrupt_pending()) {
        lamina_interrupt_clear();
        rl_replace_line("", 0);
        rl_crlf();
        rl_on_new_line();
        rl_redisplay();
    }
    return 0;
}
#endif

void repl_input_open(repl_input *in)
{
    memset(in, 0, sizeof *in);
    in->tty = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
#ifdef LAMINA_HAVE_READLINE
    if (in->tty) {
        in->readline = 1;
        rl_readline_name = "lamina";
        rl_catch_signals = 0;
        rl_signal_event_hook = on_signal_event;
        rl_bind_key('\t', rl_insert);   /* indentation, not file names */
        const char *home = getenv("HOME");
        if (home && *home) {
            snprintf(history_path, sizeof history_path, "%s/.lamina_history", home);
            read_history(history_path);
        }
        stifle_history(1000);
    }
#endif
}

char *repl_input_read(repl_input *in, const char *prompt)
{
#ifdef LAMINA_HAVE_READLINE
    if (in->readline) return readline(prompt);
#endif
    if (in->tty) {
        fputs(prompt, stdout);
        fflush(stdout);
    }
    char *line = NULL;
    size_t cap = 0;
    errno = 0;
    ssize_t n = getline(&line, &cap, stdin);
    if (n < 0) {
        int interrupted = errno == EINTR && lamina_interrupt_pending();
        clearerr(stdin);
        if (!interrupted) {
            free(line);
            return NULL;
        }
        lamina_interrupt_clear();
        if (in->tty) fputc('\n', stdout);
        if (!line) line = malloc(1);
        if (line) line[0] = 0;
        return line;
    }
    if (n > 0 && line[n - 1] == '\n') line[--n] = 0;
    if (n > 0 && line[n - 1] == '\r') line[--n] = 0;
    return line;
}

void repl_input_remember(repl_input *in, const char *entry)
{
    (void)in;
    (void)entry;
#ifdef LAMINA_HAVE_READLINE
    if (in->readline && entry[0]) add_history(entry);
#endif
}

void repl_input_close(repl_input *in)
{
#ifdef LAMINA_HAVE_READLINE
    if (in->readline && history_path[0]) write_history(history_path);
    if (in->readline) rl_clear_history();
#endif
    (void)in;
}
