/* Text beside or below the scene (a lesson page), already split into lines,
 * each with what it is (a title, a goal met, ...). The app fills it; the
 * renderer chooses how each kind looks and wraps nothing. */
#ifndef SW_APP_SIDE_H
#define SW_APP_SIDE_H

/* What a line of the side pane is; the renderer maps each to a style. */
typedef enum sw_side_kind {
    SW_SIDE_TEXT,     /* prose */
    SW_SIDE_VERBATIM, /* lines shown as written */
    SW_SIDE_TITLE,    /* headings */
    SW_SIDE_OK,       /* a goal met, a right answer */
    SW_SIDE_BAD,      /* a goal not met, a wrong answer */
    SW_SIDE_DIM,      /* key hints, the lesson's name */
    SW_SIDE_HINT      /* a hint asked for */
} sw_side_kind;

typedef struct sw_side {
    const char *const *lines;
    const sw_side_kind *kinds;  /* one per line; NULL: all SW_SIDE_TEXT */
    int nlines;
    int width;                  /* wanted columns beside the scene (0: below) */
    int *step;                  /* set by the composer: lines a press of Up or Down moves (the
                                 * text's rows less two, so a line read stays in sight) */
    int *scroll;                /* first text line shown (0: the first after the head); the
                                 * composer clamps it */
    int question_open;          /* answers of the page's open question (A..F: 2-6); 0: none open */
    int head;                   /* the first `head` lines (the lesson, the page's title) stay at
                                 * the pane's top while the text below them scrolls */
    int pinned;                 /* the last `pinned` lines (goals, question) stay in sight at the
                                 * pane's foot while the text above them scrolls; 0: none */
    int fold;                   /* of those, the last `fold` (the question, its answers, the keys'
                                 * line) fold into one line while the text above is not read to
                                 * its end, when the pane has no room for both; 0: none */
    int full;                   /* the pane takes the whole width (the reading mode), no picture */
    const char *notice;         /* what the lesson says on the key line ("page done: n next page"), or NULL */
} sw_side;

#endif
