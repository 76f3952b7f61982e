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
            "  lamina run SCRIPT.lua [--set name=value ...] [--backend cairo|osmesa] [--threads N] [--quiet]\n"
            "                          run a scenario; its frames go where it says\n"
            "                          (--report FILE: also write lamina.report values as JSON)\n"
            "                          (--out-root DIR: the files it writes must stay in DIR,\n"
            "                           by default the working directory;\n"
            "                           --lua-mem MB: its Lua memory cap, default 1024)\n"
            "  lamina diff EXPECTED.png ACTUAL.png [--out DIFF.png] [--threshold T]\n"
            "              [--max-pixels N] [--max-window N] [--hard-limit L] [--quiet]\n"
            "                          compare two images: 0 same, 1 different, 2 error\n"
            "  lamina gallery [--only PATTERN] [--force] [--check] [--compare]\n"
            "                 [--update-baselines] [--scripts DIR] [--gallery DIR]\n"
            "                 [--baselines DIR] [--work DIR] [--set name=value] [--quiet]\n"
            "                 [--timeout S] (each figure's time limit, default 1800 s)\n"
            "                          render scripts/paper/*.lua into gallery/ (docs/gallery.md)\n"
            "  lamina repl [SCRIPT.lua] [--set name=value ...] [--quiet]\n"
            "                          a Lua prompt over the script's simulation, paused\n"
            "                          before its first sim:run (docs/workbench.md)\n"
            "  lamina watch SCRIPT.lua [--steps N] [--set ...] [--max-runs N | --once]\n"
            "               [--interval S] [--log FILE] [--quiet]\n"
            "                          run again each time the script changes\n"
            "  lamina sweep SCRIPT.lua --set name=v1,v2,... [--set ...] [--jobs N]\n"
            "               [--out DIR] [--emit-jobs] [--quiet]\n"
            "  lamina sweep --collect DIR\n"
            "                          one run per combination, a summary table\n"
            "  lamina animate FOLDER|FRAME.png... [--out FILE.apng|FILE.mp4] [--fps N]\n"
            "                 [--loop N] [--quiet]\n"
            "                          a run's frames as one animation (APNG; MP4 through\n"
            "                          ffmpeg when installed; docs/rendering.md)\n"
            "  lamina bench render [--width W] [--height H] [--runs N] [--counts N,...]\n"
            "                      [--backend cairo|osmesa|all]\n"
            "                          milliseconds per frame for each renderer\n"
            "  lamina bench engine [--sizes N,...] [--work PARTICLE_STEPS] [--threads N]\n"
            "                          particle-steps per second of the step, one thread\n"
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
    if (strcmp(cmd, "animate") == 0) return cmd_animate(argc - 2, argv + 2);
    if (strcmp(cmd, "bench") == 0) return cmd_bench(argc - 2, argv + 2);
    if (strcmp(cmd, "diff") == 0) return cmd_diff(argc - 2, argv + 2);
    if (strcmp(cmd, "gallery") == 0) return cmd_gallery(argc - 2, argv + 2);
    if (strcmp(cmd, "repl") == 0) return cmd_repl(argc - 2, argv + 2);
    if (strcmp(cmd, "watch") == 0) return cmd_watch(argc - 2, argv + 2);
    if (strcmp(cmd, "sweep") == 0) return cmd_sweep(argc - 2, argv + 2);
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
