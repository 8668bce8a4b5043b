/* stepwise: the command line. Parses subcommands and hands them to the lab,
 * lesson and tui layers. Only this file and the TUI talk to the user. */
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "stepwise/scene.h"
#include "stepwise/sim.h"

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "--version") == 0) {
        printf("stepwise %s\n", SW_VERSION);
        return 0;
    }
    for (int i = 0; i < sw_scene_count(); i++)
        printf("%-14s %s\n", sw_scene_at(i)->name, sw_scene_at(i)->summary);
    return 0;
}
