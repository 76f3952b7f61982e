/* main.c - the `lamina` command: dispatch to its sub-commands. */
#include <stdio.h>
#include <string.h>

#include "app.h"

static void usage(FILE *out)
{
    fprintf(out,
            "lamina %s - membranes, gas and their interaction with the material point method\n"
            "\n"
            "usage:\n"
            "  lamina run SCRIPT.lua [--set name=value ...] [--quiet]\n"
            "                          run a scenario; its frames go where it says\n"
            "  lamina help             this text\n"
            "  lamina --version        the version\n"
            "\n"
            "exit status: 0 success, 1 the simulation failed (instability, a particle\n"
            "left the domain), 2 the script or the command line is wrong.\n"
            "The Lua API is described in docs/api.md.\n",
            LAMINA_VERSION);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "run") == 0) return cmd_run(argc - 2, argv + 2);
    if (strcmp(cmd, "help") == 0 || strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "version") == 0) {
        printf("lamina %s\n", LAMINA_VERSION);
        return 0;
    }
    fprintf(stderr, "lamina: unknown command '%s' (try 'lamina help')\n", cmd);
    return 2;
}
