/* main.c - the `lamina` command: dispatch to its sub-commands. The exit
 * status is the sub-command's (lamina run: from its run's recorded failure,
 * lamina_failure_status in src/lua/l_run_guard.c); a wrong command line is
 * LAMINA_EXIT_USAGE. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "app.h"
#include "lamina_lua.h"
#include "util.h"

/* LAMINA_MEMORY_MB: the process's one memory cap (src/util/lu_budget.c;
 * default LU_BUDGET_DEFAULT_MB), for every command. 0, or -1 after saying
 * what is wrong with it. */
static int memory_from_env(void)
{
    const char *v = getenv("LAMINA_MEMORY_MB");
    if (!v) return 0;
    char *end = NULL;
    double mb = strtod(v, &end);
    if (!*v || *end || !(mb >= 16 && mb <= 1048576)) {
        fprintf(stderr, "lamina: LAMINA_MEMORY_MB='%s': needs a size in MB from 16 to 1048576 "
                "(default %d)\n", v, LU_BUDGET_DEFAULT_MB);
        return -1;
    }
    lu_budget_set_limit((size_t)(mb * 1048576.0));
    return 0;
}

int main(int argc, char **argv)
{
    app_wait_policy(argv);
    if (memory_from_env() != 0) return LAMINA_EXIT_USAGE;
    if (argc < 2) {
        app_usage(stderr);
        return LAMINA_EXIT_USAGE;
    }
    const char *cmd = argv[1];
    static const char *const known[] = {"run", "animate", "bench", "diff", "gallery",
                                        "repl", "watch", "sweep", "serve", NULL};
    for (int k = 0; known[k]; k++)   /* lamina CMD ... --help (help.c) */
        if (strcmp(cmd, known[k]) == 0 && app_wants_help(argc - 2, argv + 2))
            return app_command_help(stdout, cmd, argc > 2 ? argv[2] : NULL);
    if (strcmp(cmd, "run") == 0) return cmd_run(argc - 2, argv + 2);
    if (strcmp(cmd, "animate") == 0) return cmd_animate(argc - 2, argv + 2);
    if (strcmp(cmd, "bench") == 0) return cmd_bench(argc - 2, argv + 2);
    if (strcmp(cmd, "diff") == 0) return cmd_diff(argc - 2, argv + 2);
    if (strcmp(cmd, "gallery") == 0) return cmd_gallery(argc - 2, argv + 2);
    if (strcmp(cmd, "repl") == 0) return cmd_repl(argc - 2, argv + 2);
    if (strcmp(cmd, "watch") == 0) return cmd_watch(argc - 2, argv + 2);
    if (strcmp(cmd, "sweep") == 0) return cmd_sweep(argc - 2, argv + 2);
    if (strcmp(cmd, "serve") == 0) return cmd_serve(argc - 2, argv + 2);
    if (strcmp(cmd, "help") == 0 || strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        if (argc > 2) return app_command_help(stdout, argv[2], argc > 3 ? argv[3] : NULL);
        app_usage(stdout);
        return LAMINA_EXIT_OK;
    }
    if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "version") == 0) {
        printf("lamina %s\n", LAMINA_VERSION);
        return LAMINA_EXIT_OK;
    }
    fprintf(stderr, "lamina: unknown command '%s' (try 'lamina help')\n", cmd);
    return LAMINA_EXIT_USAGE;
}
