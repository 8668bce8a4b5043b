/* The key table: one row per key, read by the key handler and by the `?`
 * help screen, so the help can never disagree with what the keys do
 * (after htop's Action.c). */
#include "app/app.h"

#include <stddef.h>

static const sw_keybinding table[] = {
    { 'i', SW_ACT_NEXT_METHOD, 0, "i  Tab", "next integrator (keeps the state and time)", 0 },
    { SW_KEY_TAB, SW_ACT_NEXT_METHOD, 0, NULL, NULL, 0 },
    { 'I', SW_ACT_PREV_METHOD, 0, "I  Shift-Tab", "previous integrator", 0 },
    { SW_KEY_BTAB, SW_ACT_PREV_METHOD, 0, NULL, NULL, 0 },
    { '1', SW_ACT_PICK_METHOD, 1, "1-9  0", "pick an integrator by its place in 'stepwise list integrators' (0: the 10th)", 0 },
    { '2', SW_ACT_PICK_METHOD, 2, NULL, NULL, 0 },
    { '3', SW_ACT_PICK_METHOD, 3, NULL, NULL, 0 },
    { '4', SW_ACT_PICK_METHOD, 4, NULL, NULL, 0 },
    { '5', SW_ACT_PICK_METHOD, 5, NULL, NULL, 0 },
    { '6', SW_ACT_PICK_METHOD, 6, NULL, NULL, 0 },
    { '7', SW_ACT_PICK_METHOD, 7, NULL, NULL, 0 },
    { '8', SW_ACT_PICK_METHOD, 8, NULL, NULL, 0 },
    { '9', SW_ACT_PICK_METHOD, 9, NULL, NULL, 0 },
    { '0', SW_ACT_PICK_METHOD, 10, NULL, NULL, 0 },
    { '+', SW_ACT_DT_DOUBLE, 0, "+  =", "double dt", 0 },
    { '=', SW_ACT_DT_DOUBLE, 0, NULL, NULL, 0 },
    { '-', SW_ACT_DT_HALVE, 0, "-", "halve dt", 0 },
    { ' ', SW_ACT_PAUSE, 0, "space", "pause / run", 0 },
    { '.', SW_ACT_STEP, 0, ".", "one step (pauses)", 0 },
    { 'r', SW_ACT_RESET, 0, "r", "reset to t = 0", 0 },
    { '[', SW_ACT_SLOWER, 0, "[  ]", "slower / faster simulated time", 0 },
    { ']', SW_ACT_FASTER, 0, NULL, NULL, 0 },
    { 'c', SW_ACT_COMPARE, 0, "c", "compare: the same scene under two more integrators", 0 },
    { 'g', SW_ACT_GHOST, 0, "g", "ghost: the exact solution (or a reference run) beside yours", 0 },
    { 't', SW_ACT_TRAILS, 0, "t", "trails", 0 },
    { 'e', SW_ACT_GRAPH, 0, "e", "graph of energy drift (or error) against time", 0 },
    { 'b', SW_ACT_BRAILLE, 0, "b", "Braille dots (finer picture)", 0 },
    { 'p', SW_ACT_PANEL, 0, "p", "parameter panel: Up/Down choose, Left/Right change", 0 },
    { 'R', SW_ACT_RECORD, 0, "R", "start / stop recording a trace (restarts at t = 0)", 0 },
    { 'w', SW_ACT_WORKPREC, 0, "w", "work-precision plot: error against cost", 0 },
    { '?', SW_ACT_HELP, 0, "?", "this help", 0 },
    { 'q', SW_ACT_QUIT, 0, "q", "quit", 0 },
    { 'n', SW_ACT_PAGE_NEXT, 0, "n  PgDn", "next page (once its goals are met)", 1 },
    { SW_KEY_PGDN, SW_ACT_PAGE_NEXT, 0, NULL, NULL, 1 },
    { 'N', SW_ACT_PAGE_PREV, 0, "N  PgUp", "previous page", 1 },
    { SW_KEY_PGUP, SW_ACT_PAGE_PREV, 0, NULL, NULL, 1 },
    { 'h', SW_ACT_HINT, 0, "h", "hint for the first goal not met", 1 },
    { SW_KEY_UP, SW_ACT_SCROLL_UP, 0, "Up  Down", "scroll the lesson text", 1 },
    { SW_KEY_DOWN, SW_ACT_SCROLL_DOWN, 0, NULL, NULL, 1 },
    /* While a page's question is open the lesson runner reads a-f as answers
     * before this table (b, c and e mean Braille, compare and graph otherwise);
     * key -1 never arrives, so this row only shows in the help screen. */
    { -1, SW_ACT_ANSWER, 0, "a-f", "answer the page's question (while it is open)", 1 },
};

static const sw_keybinding panel_keys[] = {
    { SW_KEY_UP, SW_ACT_PANEL_UP, 0, "Up", "previous parameter", 0 },
    { SW_KEY_DOWN, SW_ACT_PANEL_DOWN, 0, "Down", "next parameter", 0 },
    { SW_KEY_LEFT, SW_ACT_PANEL_DEC, 0, "Left", "decrease (within its range)", 0 },
    { SW_KEY_RIGHT, SW_ACT_PANEL_INC, 0, "Right", "increase (within its range)", 0 },
    { SW_KEY_ESC, SW_ACT_PANEL, 0, "Esc", "close the panel", 0 },
};

const sw_keybinding *sw_keys(int *count)
{
    *count = (int)(sizeof table / sizeof table[0]);
    return table;
}

const sw_keybinding *sw_key_lookup(int key, int panel_open, int in_lesson)
{
    if (panel_open)
        for (size_t i = 0; i < sizeof panel_keys / sizeof panel_keys[0]; i++)
            if (panel_keys[i].key == key)
                return &panel_keys[i];
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (table[i].key == key && (in_lesson || !table[i].lesson_only))
            return &table[i];
    return NULL;
}

const char *sw_action_name(sw_action a)
{
    static const char *const names[SW_ACT_COUNT] = {
        [SW_ACT_NONE] = "nothing", [SW_ACT_NEXT_METHOD] = "next integrator",
        [SW_ACT_PREV_METHOD] = "previous integrator", [SW_ACT_PICK_METHOD] = "pick integrator",
        [SW_ACT_DT_DOUBLE] = "double dt", [SW_ACT_DT_HALVE] = "halve dt", [SW_ACT_PAUSE] = "pause",
        [SW_ACT_STEP] = "single step", [SW_ACT_RESET] = "reset", [SW_ACT_SLOWER] = "slower",
        [SW_ACT_FASTER] = "faster", [SW_ACT_COMPARE] = "compare", [SW_ACT_GHOST] = "ghost",
        [SW_ACT_TRAILS] = "trails", [SW_ACT_GRAPH] = "graph", [SW_ACT_BRAILLE] = "Braille",
        [SW_ACT_PANEL] = "parameter panel", [SW_ACT_PANEL_UP] = "parameter up",
        [SW_ACT_PANEL_DOWN] = "parameter down", [SW_ACT_PANEL_DEC] = "decrease parameter",
        [SW_ACT_PANEL_INC] = "increase parameter", [SW_ACT_RECORD] = "record",
        [SW_ACT_WORKPREC] = "work-precision plot", [SW_ACT_HELP] = "help", [SW_ACT_QUIT] = "quit",
        [SW_ACT_PAGE_NEXT] = "next page", [SW_ACT_PAGE_PREV] = "previous page", [SW_ACT_HINT] = "hint",
        [SW_ACT_ANSWER] = "answer", [SW_ACT_SCROLL_UP] = "scroll up", [SW_ACT_SCROLL_DOWN] = "scroll down",
    };
    return a >= 0 && a < SW_ACT_COUNT && names[a] ? names[a] : "unknown";
}
