/* The stage view's scripts: each drawn method's step as the lecture writes
 * it (see lecture.h). Invariant: a script's SLOPE views name stages in the
 * order the method's step function evaluates them (sim/stages.c records
 * them so), and its lines are the arithmetic that function does. */
#include "engine/lecture.h"

const sw_stage_script sw_lecture_euler = {
    .lines = { "k1 = f(t, y)", "y = y + h*k1", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_SLOPE, .label = "k1",
                 .caption = "k1: the slope where the step starts" },
               { .line = 1, .stage = 0, .shape = SW_STAGE_SUM, .label = "y1",
                 .caption = "y1: Euler follows k1 for the whole step" } },
    .nviews = 2,
};

const sw_stage_script sw_lecture_midpoint = {
    .lines = { "k1 = f(t, y)", "k2 = f(t + h/2, y + h/2*k1)", "y = y + h*k2", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_SLOPE, .label = "k1",
                 .caption = "k1: the slope at the start" },
               { .line = 1, .stage = 1, .shape = SW_STAGE_SLOPE, .label = "k2",
                 .caption = "k2: the slope half a step along k1" },
               { .line = 2, .stage = 0, .shape = SW_STAGE_SUM, .label = "y1",
                 .caption = "y1: the whole step on the middle's slope k2" } },
    .nviews = 3,
};

const sw_stage_script sw_lecture_heun = {
    .lines = { "k1 = f(t, y)", "k2 = f(t + h, y + h*k1)", "y = y + h/2*(k1 + k2)", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_SLOPE, .label = "k1",
                 .caption = "k1: the predictor's slope, at the start" },
               { .line = 1, .stage = 1, .shape = SW_STAGE_SLOPE, .label = "k2",
                 .caption = "k2: the corrector's slope, at the end of an Euler step" },
               { .line = 2, .stage = 0, .shape = SW_STAGE_SUM, .label = "y1",
                 .caption = "y1: the step on the average of k1 and k2" } },
    .nviews = 3,
};

const sw_stage_script sw_lecture_rk4 = {
    .lines = { "k1 = f(t, y)", "k2 = f(t + h/2, y + h/2*k1)", "k3 = f(t + h/2, y + h/2*k2)",
               "k4 = f(t + h, y + h*k3)", "y = y + h/6*(k1+2*k2+2*k3+k4)", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_SLOPE, .label = "k1",
                 .caption = "k1: the slope at the start" },
               { .line = 1, .stage = 1, .shape = SW_STAGE_SLOPE, .label = "k2",
                 .caption = "k2: the slope half a step along k1" },
               { .line = 2, .stage = 2, .shape = SW_STAGE_SLOPE, .label = "k3",
                 .caption = "k3: the slope half a step along k2" },
               { .line = 3, .stage = 3, .shape = SW_STAGE_SLOPE, .label = "k4",
                 .caption = "k4: the slope a whole step along k3" },
               { .line = 4, .stage = 0, .shape = SW_STAGE_SUM, .label = "y1",
                 .caption = "y1: the weighted sum, weights 1 2 2 1 over 6" } },
    .nviews = 5,
};

const sw_stage_script sw_lecture_symplectic_euler = {
    .lines = { "a = a(x, v)", "v = v + h*a", "x = x + h*v", "t = t + h" },
    .views = { { .line = 1, .stage = 0, .shape = SW_STAGE_KICK, .label = "v1",
                 .caption = "kick: v changes by h*a, taken at the old x (dim: before)" },
               { .line = 2, .stage = 0, .shape = SW_STAGE_DRIFT, .label = "x1",
                 .caption = "drift: x moves a step with the new v" } },
    .nviews = 2,
};

const sw_stage_script sw_lecture_verlet = {
    .lines = { "v = v + h/2*a   (a: last step's)", "x = x + h*v", "a = a(x, v)", "v = v + h/2*a", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_KICK, .label = "v'",
                 .caption = "half kick: v changes by h/2*a (dim: v before)" },
               { .line = 1, .stage = 0, .shape = SW_STAGE_DRIFT, .label = "x1",
                 .caption = "drift: x moves a whole step with the half-kicked v" },
               { .line = 3, .stage = 1, .shape = SW_STAGE_KICK_END, .label = "v1",
                 .caption = "a at the new x, then the second half kick" } },
    .nviews = 3,
};
