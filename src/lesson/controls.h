/* The student's controls: ONE list (after tig's request.h) of every action a
 * key can trigger, with its keys, its name in messages, the lock group a
 * lesson page uses to take it away, and its line on the help screen. The
 * action enum, the key table, the help screen and the lesson lock names are
 * all generated from it, so they can never disagree. It lives in lesson/
 * because both the lesson parser (lock names) and the app (keys, actions)
 * read it, and the app sits above the lessons. */
#ifndef SW_LESSON_CONTROLS_H
#define SW_LESSON_CONTROLS_H

#include <limits.h>
#include <stddef.h>
#include <stdint.h>

/* Special keys, independent of curses (the front end translates). */
enum {
    SW_KEY_NONE = -1,  /* never arrives: a control shown in help only */
    SW_KEY_UP = 0x10000, SW_KEY_DOWN, SW_KEY_LEFT, SW_KEY_RIGHT, SW_KEY_TAB, SW_KEY_BTAB,
    SW_KEY_PGDN, SW_KEY_PGUP, SW_KEY_ESC
};

/* Lock groups, as a lesson names them (`@lock integrator dt`). */
#define SW_LOCK_GROUPS(G) \
    G(INTEGRATOR, "integrator") \
    G(DT,         "dt")         \
    G(RUN,        "run")        \
    G(RESET,      "reset")      \
    G(SPEED,      "speed")      \
    G(COMPARE,    "compare")    \
    G(GHOST,      "ghost")      \
    G(TRAILS,     "trails")     \
    G(GRAPH,      "graph")      \
    G(BRAILLE,    "braille")    \
    G(PARAMS,     "params")     \
    G(RECORD,     "record")     \
    G(PLOT,       "plot")       \
    G(VIEW,       "view")       \
    G(EVENTS,     "events")

#define SW_KEYS(...) { __VA_ARGS__, 0 }

/* The keys that pick an integrator by its place in the table ('stepwise list
 * integrators'): 1-9, 0 for the 10th, then the shifted digits and the
 * shifted keys beside them, so every built-in and every plugin (at most
 * SW_PICK_KEY_COUNT in all) has one. */
#define SW_PICK_KEYS '1', '2', '3', '4', '5', '6', '7', '8', '9', '0', \
                     '!', '@', '#', '$', '%', '^', '&', '*', '(', ')', '_', '{', '}', '|', \
                     '~', ':', '"', '/'
#define SW_PICK_KEY_COUNT 28

/* The answer keys: SW_ANSWER_FIRST + i answers choice i (a) .. f)). */
#define SW_ANSWER_FIRST 'A'

/* X(ACTION, LOCK, CONTEXT, NAME, KEYS, HELP_KEYS, HELP)
 *   ACTION     the action is SW_ACT_<ACTION>
 *   LOCK       the lock group (SW_LOCK_<LOCK>) that takes it away; NONE: never locked
 *   CONTEXT    PLAY: always; LESSON: in a lesson only; PANEL: while the parameter panel is open
 *   NAME       how messages name it ("'double dt' is locked on this page")
 *   KEYS       its keys, characters or SW_KEY_*; a key's place in the list (1-based) is the
 *              argument the action gets (SW_PICK_KEYS: the place of the integrator picked)
 *   HELP_KEYS  how the help screen names its keys; NULL: on the help line before it
 *              (pick integrator's keys and line are generated from the integrator table)
 *   HELP       the help line (NULL with HELP_KEYS NULL)
 * Help shows PLAY controls, and LESSON ones in a lesson, in this order. */
#define SW_CONTROLS(X) \
    X(NEXT_METHOD, INTEGRATOR, PLAY, "next integrator", SW_KEYS('i', SW_KEY_TAB), \
      "i  Tab", "next integrator (the run starts again at t = 0, paused)") \
    X(PREV_METHOD, INTEGRATOR, PLAY, "previous integrator", SW_KEYS('I', SW_KEY_BTAB), \
      "I  Shift-Tab", "previous integrator") \
    X(PICK_METHOD, INTEGRATOR, PLAY, "pick integrator", SW_KEYS(SW_PICK_KEYS), \
      "1-9  0", "pick an integrator by its place in 'stepwise list integrators'") \
    X(DT_DOUBLE, DT, PLAY, "double dt", SW_KEYS('+', '='), "+  -", \
      "double / halve dt (the run starts again at t = 0, paused)") \
    X(DT_HALVE, DT, PLAY, "halve dt", SW_KEYS('-'), NULL, NULL) \
    X(PAUSE, RUN, PLAY, "pause", SW_KEYS(' '), "space", "run / pause: the one key that runs (every restart is paused)") \
    X(STEP, RUN, PLAY, "single step", SW_KEYS('.'), ".  ,  ;  u", \
      "one step on / back, 50 back (pauses); u: run to the stop time (--until, @until)") \
    X(BACK, RUN, PLAY, "step back", SW_KEYS(','), NULL, NULL) \
    X(BACK_MANY, RUN, PLAY, "rewind", SW_KEYS(';'), NULL, NULL) \
    X(UNTIL, RUN, PLAY, "run to the stop time", SW_KEYS('u'), NULL, NULL) \
    X(RESET, RESET, PLAY, "reset", SW_KEYS('r'), "r", "reset to t = 0, paused") \
    X(SLOWER, SPEED, PLAY, "slower", SW_KEYS('['), "[  ]", "slower / faster simulated time") \
    X(FASTER, SPEED, PLAY, "faster", SW_KEYS(']'), NULL, NULL) \
    X(COMPARE, COMPARE, PLAY, "compare", SW_KEYS('c'), \
      "c", "compare: the same scene under two more integrators (all from t = 0, paused)") \
    X(GHOST, GHOST, PLAY, "ghost", SW_KEYS('g'), \
      "g", "ghost: the exact solution (or a reference run) beside yours") \
    X(TRAILS, TRAILS, PLAY, "trails", SW_KEYS('t'), "t", "trails") \
    X(GRAPH, GRAPH, PLAY, "graph", SW_KEYS('e'), "e", "graph of energy drift (or error) against time") \
    X(ERROR_KIND, NONE, PLAY, "error kind", SW_KEYS('m'), "m", \
      "err: position error (m) / velocity error (m/s)") \
    X(BRAILLE, BRAILLE, PLAY, "Braille", SW_KEYS('b'), "b", "Braille dots (finer picture)") \
    X(PANEL, PARAMS, PLAY, "parameter panel", SW_KEYS('p'), \
      "p", "parameter panel: Up/Down choose, Left/Right change") \
    X(RECORD, RECORD, PLAY, "record", SW_KEYS('R'), \
      "R", "start / stop recording a trace (restarts at t = 0)") \
    X(WORKPREC, PLOT, PLAY, "work-precision plot", SW_KEYS('w'), \
      "w", "work-precision plot: error against cost") \
    X(ZOOM_OUT, VIEW, PLAY, "zoom out", SW_KEYS('z'), "z  Z", "zoom out / in (scene, phase and region views)") \
    X(ZOOM_IN, VIEW, PLAY, "zoom in", SW_KEYS('Z'), NULL, NULL) \
    X(FOLLOW, VIEW, PLAY, "follow", SW_KEYS('f'), "f", "camera follows the particles / stays on the scene") \
    X(LANES, VIEW, PLAY, "side by side", SW_KEYS('l'), "l", "compare side by side (lanes) / overlaid") \
    X(PHASE, VIEW, PLAY, "phase view", SW_KEYS('v'), "v", "phase view: a coordinate against its velocity") \
    X(PHASE_COORD, VIEW, PLAY, "phase coordinate", SW_KEYS('V'), "V  <  >", "phase view: next coordinate, particle") \
    X(PHASE_PREV, VIEW, PLAY, "previous particle", SW_KEYS('<'), NULL, NULL) \
    X(PHASE_NEXT, VIEW, PLAY, "next particle", SW_KEYS('>'), NULL, NULL) \
    X(REGION, VIEW, PLAY, "stability region", SW_KEYS('s'), "s", "stability region of the method, dt x eigenvalues") \
    X(STAGES, VIEW, PLAY, "stages of a step", SW_KEYS('k'), "k  Esc", \
      "stages of one step drawn: k1, k2, ... one per press (pauses); Esc closes") \
    X(STAGES_CLOSE, NONE, PLAY, "close the stages", SW_KEYS(SW_KEY_ESC), NULL, NULL) \
    X(EVENTS, EVENTS, PLAY, "events", SW_KEYS('x'), \
      "x", "events: locate contacts and crossings / step over them") \
    X(HELP, NONE, PLAY, "help", SW_KEYS('?'), "?", "this help (again: next page)") \
    X(QUIT, NONE, PLAY, "quit", SW_KEYS('q'), "q", "quit") \
    X(PAGE_NEXT, NONE, LESSON, "next page", SW_KEYS('n', SW_KEY_PGDN), \
      "n  PgDn", "next page (once its goals are met)") \
    X(PAGE_PREV, NONE, LESSON, "previous page", SW_KEYS('N', SW_KEY_PGUP), "N  PgUp", "previous page") \
    X(HINT, NONE, LESSON, "hint", SW_KEYS('h'), "h", "hint for the first goal not met") \
    X(SCROLL_UP, NONE, LESSON, "scroll up", SW_KEYS(SW_KEY_UP), "Up  Down", "scroll the lesson text") \
    X(SCROLL_DOWN, NONE, LESSON, "scroll down", SW_KEYS(SW_KEY_DOWN), NULL, NULL) \
    X(READ, NONE, LESSON, "reading mode", SW_KEYS('o'), "o", \
      "reading mode: the lesson text full width / beside the picture again") \
    /* Capital letters answer a page's question: no play key is a capital \
     * A-F (SW_ANSWER_FIRST; a test keeps it so), so an answer never toggles \
     * a view and a play key never answers. */ \
    X(ANSWER, NONE, LESSON, "answer", SW_KEYS('A', 'B', 'C', 'D', 'E', 'F'), \
      "A-F", "answer the page's question (capital letters)") \
    X(PANEL_UP, PARAMS, PANEL, "parameter up", SW_KEYS(SW_KEY_UP), "Up", "previous parameter") \
    X(PANEL_DOWN, PARAMS, PANEL, "parameter down", SW_KEYS(SW_KEY_DOWN), "Down", "next parameter") \
    X(PANEL_DEC, PARAMS, PANEL, "decrease parameter", SW_KEYS(SW_KEY_LEFT), "Left", "decrease (within its range)") \
    X(PANEL_INC, PARAMS, PANEL, "increase parameter", SW_KEYS(SW_KEY_RIGHT), "Right", "increase (within its range)") \
    X(PANEL_CLOSE, PARAMS, PANEL, "close the panel", SW_KEYS(SW_KEY_ESC), "Esc", "close the panel")

typedef enum sw_action {
    SW_ACT_NONE,
#define SW_X(action, lock, context, name, keys, help_keys, help) SW_ACT_##action,
    SW_CONTROLS(SW_X)
#undef SW_X
    SW_ACT_COUNT
} sw_action;

/* The case labels of one context's actions, generated from the list
 * (SW_LESSON_CASES: `case SW_ACT_PAGE_NEXT: case ...:`). A switch over
 * actions has no default (STYLE.md): it names the actions another module
 * handles with these, so -Wswitch names it when a control is added. */
#define SW_CASE_IF_PLAY_PLAY(action) case SW_ACT_##action:
#define SW_CASE_IF_PLAY_LESSON(action)
#define SW_CASE_IF_PLAY_PANEL(action)
#define SW_CASE_IF_LESSON_PLAY(action)
#define SW_CASE_IF_LESSON_LESSON(action) case SW_ACT_##action:
#define SW_CASE_IF_LESSON_PANEL(action)
#define SW_CASE_IF_PANEL_PLAY(action)
#define SW_CASE_IF_PANEL_LESSON(action)
#define SW_CASE_IF_PANEL_PANEL(action) case SW_ACT_##action:
#define SW_X_PLAY_CASE(action, lock, context, ...) SW_CASE_IF_PLAY_##context(action)
#define SW_X_LESSON_CASE(action, lock, context, ...) SW_CASE_IF_LESSON_##context(action)
#define SW_X_PANEL_CASE(action, lock, context, ...) SW_CASE_IF_PANEL_##context(action)
#define SW_PLAY_CASES SW_CONTROLS(SW_X_PLAY_CASE)
#define SW_LESSON_CASES SW_CONTROLS(SW_X_LESSON_CASE)
#define SW_PANEL_CASES SW_CONTROLS(SW_X_PANEL_CASE)

/* Lock groups: a bit each in an sw_lock_mask. */
enum {
#define SW_G(group, name) SW_LOCK_BIT_##group,
    SW_LOCK_GROUPS(SW_G)
#undef SW_G
    SW_LOCK_NGROUPS
};

typedef uint32_t sw_lock_mask;
_Static_assert(SW_LOCK_NGROUPS <= (int)(sizeof(sw_lock_mask) * CHAR_BIT),
               "sw_lock_mask needs a bit for every lock group in SW_LOCK_GROUPS");

enum {
    SW_LOCK_NONE = 0,
#define SW_G(group, name) SW_LOCK_##group = 1 << SW_LOCK_BIT_##group,
    SW_LOCK_GROUPS(SW_G)
#undef SW_G
    SW_LOCK_ALL = (int)((1ull << SW_LOCK_NGROUPS) - 1)
};

/* Where a control's keys work. */
typedef enum sw_control_context {
    SW_CTX_PLAY = 1,    /* always (play and lessons) */
    SW_CTX_LESSON = 2,  /* in a lesson only */
    SW_CTX_PANEL = 4    /* while the parameter panel is open, before the others */
} sw_control_context;

typedef struct sw_control {
    sw_action action;
    sw_lock_mask lock;        /* the group that locks it; 0: never locked */
    sw_control_context context;
    const char *name;
    const int *keys;          /* ends with 0 */
    const char *help_keys;    /* NULL: listed on the help line before */
    const char *help;
} sw_control;

/* Every control in list order; *count of them (SW_ACT_COUNT - 1). */
const sw_control *sw_controls(int *count);
/* The control of an action; NULL for SW_ACT_NONE or out of range. */
const sw_control *sw_control_of(sw_action a);
/* How messages name an action ("double dt"); "nothing" for none. */
const char *sw_action_name(sw_action a);

/* What a key does in the given contexts (SW_CTX_* bits; panel controls are
 * tried first): 1 with *control and *arg (the key's 1-based place among the
 * control's keys), or 0 when the key is not bound there. */
int sw_key_lookup(int key, unsigned contexts, const sw_control **control, int *arg);
/* The contexts a live key is looked up in: play always, the parameter
 * panel while it is open, a lesson's keys inside one. */
unsigned sw_key_contexts(int panel, int in_lesson);
/* A key by its name as written in drive files and lessons ("space", "tab",
 * "up", "esc", ...; a single character is itself); SW_KEY_NONE when unknown. */
int sw_key_find(const char *name);

/* The lock group of a key in play (SW_LOCK_*), 0 when it cannot be locked
 * (navigation, help, quit, unbound). */
sw_lock_mask sw_lock_of_key(int key);
/* The name of one lock group bit ("integrator"), or NULL. */
const char *sw_lock_name(sw_lock_mask bit);
/* A lock as a lesson writes it: a group name, "all", or one of its keys
 * (a character or a key name); 0 when the word names none. */
sw_lock_mask sw_lock_find(const char *word);
/* What sw_lock_find accepts, for messages: "integrator, dt, ..., all, or one
 * of their keys (i I 1 + ...)". Returns the bytes written. */
size_t sw_lock_describe(char *buf, size_t len);

#endif
