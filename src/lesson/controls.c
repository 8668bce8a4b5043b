/* The tables generated from SW_CONTROLS and SW_LOCK_GROUPS, and the lookups
 * over them. Invariant: nothing here lists a control by hand; adding a row
 * to the list adds its action, keys, help line and lock. */
#include "lesson/controls.h"

#include <stdio.h>
#include <string.h>

#include "stepwise/integrator.h"

/* Every method the table can hold has a key that picks it, and
 * SW_PICK_KEY_COUNT counts the keys SW_PICK_KEYS lists. */
_Static_assert(SW_PICK_KEY_COUNT >= SW_METHODS_MAX,
               "SW_PICK_KEYS needs a key for each of the SW_METHODS_MAX methods (stepwise/integrator.h)");
_Static_assert(sizeof (int[]){ SW_PICK_KEYS } / sizeof(int) == SW_PICK_KEY_COUNT,
               "SW_PICK_KEY_COUNT must count the keys in SW_PICK_KEYS");

#define SW_X(action, lock, context, name, keys, help_keys, help) \
    static const int keys_##action[] = keys;
SW_CONTROLS(SW_X)
#undef SW_X

static const sw_control controls[] = {
#define SW_X(action, lock, context, name, keys, help_keys, help) \
    { SW_ACT_##action, SW_LOCK_##lock, SW_CTX_##context, name, keys_##action, help_keys, help },
    SW_CONTROLS(SW_X)
#undef SW_X
};

#define NCONTROLS ((int)(sizeof controls / sizeof controls[0]))
_Static_assert(NCONTROLS == SW_ACT_COUNT - 1, "one control per action");

static const char *const group_names[SW_LOCK_NGROUPS] = {
#define SW_G(group, name) name,
    SW_LOCK_GROUPS(SW_G)
#undef SW_G
};

static const struct { const char *name; int key; } key_names[] = {
    { "space", ' ' }, { "tab", SW_KEY_TAB }, { "btab", SW_KEY_BTAB }, { "pgdn", SW_KEY_PGDN },
    { "pgup", SW_KEY_PGUP }, { "up", SW_KEY_UP }, { "down", SW_KEY_DOWN }, { "left", SW_KEY_LEFT },
    { "right", SW_KEY_RIGHT }, { "esc", SW_KEY_ESC },
};

const sw_control *sw_controls(int *count)
{
    *count = NCONTROLS;
    return controls;
}

const sw_control *sw_control_of(sw_action a)
{
    return a > SW_ACT_NONE && a < SW_ACT_COUNT ? &controls[a - 1] : NULL;
}

const char *sw_action_name(sw_action a)
{
    const sw_control *c = sw_control_of(a);
    return a == SW_ACT_NONE ? "nothing" : c ? c->name : "unknown";
}

static int find_in(int key, sw_control_context context, const sw_control **control, int *arg)
{
    for (int i = 0; i < NCONTROLS; i++) {
        if (controls[i].context != context)
            continue;
        for (int k = 0; controls[i].keys[k]; k++)
            if (controls[i].keys[k] == key && key != SW_KEY_NONE) {
                *control = &controls[i];
                *arg = k + 1;
                return 1;
            }
    }
    return 0;
}

unsigned sw_key_contexts(int panel, int in_lesson)
{
    return SW_CTX_PLAY | (panel ? SW_CTX_PANEL : 0u) | (in_lesson ? SW_CTX_LESSON : 0u);
}

int sw_key_lookup(int key, unsigned contexts, const sw_control **control, int *arg)
{
    static const sw_control_context order[] = { SW_CTX_PANEL, SW_CTX_PLAY, SW_CTX_LESSON };
    for (size_t i = 0; i < sizeof order / sizeof order[0]; i++)
        if ((contexts & order[i]) && find_in(key, order[i], control, arg))
            return 1;
    return 0;
}

int sw_key_find(const char *name)
{
    for (size_t i = 0; i < sizeof key_names / sizeof key_names[0]; i++)
        if (strcmp(name, key_names[i].name) == 0)
            return key_names[i].key;
    return name[0] && !name[1] ? (unsigned char)name[0] : SW_KEY_NONE;
}

sw_lock_mask sw_lock_of_key(int key)
{
    const sw_control *c;
    int arg;
    return find_in(key, SW_CTX_PLAY, &c, &arg) ? c->lock : 0;
}

const char *sw_lock_name(sw_lock_mask bit)
{
    for (int g = 0; g < SW_LOCK_NGROUPS; g++)
        if (bit == (sw_lock_mask)1 << g)
            return group_names[g];
    return NULL;
}

sw_lock_mask sw_lock_find(const char *word)
{
    for (int g = 0; g < SW_LOCK_NGROUPS; g++)
        if (strcmp(word, group_names[g]) == 0)
            return (sw_lock_mask)1 << g;
    if (strcmp(word, "all") == 0)
        return SW_LOCK_ALL;
    int key = sw_key_find(word);
    return key == SW_KEY_NONE ? 0 : sw_lock_of_key(key);
}

/* A key as a lesson would write it. */
static void key_text(int key, char *buf, size_t len)
{
    for (size_t i = 0; i < sizeof key_names / sizeof key_names[0]; i++)
        if (key_names[i].key == key) {
            snprintf(buf, len, "%s", key_names[i].name);
            return;
        }
    snprintf(buf, len, "%c", key > 0 && key < 0x7F ? key : '?');
}

size_t sw_lock_describe(char *buf, size_t len)
{
    size_t used = 0;
    if (!len)
        return 0;
    buf[0] = '\0';
#define ADD(...) do { int w_ = snprintf(buf + used, len - used, __VA_ARGS__); \
        used += w_ < 0 ? 0 : (size_t)w_ < len - used ? (size_t)w_ : len - used - 1; } while (0)
    for (int g = 0; g < SW_LOCK_NGROUPS; g++)
        ADD("%s, ", group_names[g]);
    ADD("all, or one of their keys (");
    int first = 1;
    for (int i = 0; i < NCONTROLS; i++) {
        if (!controls[i].lock || controls[i].context != SW_CTX_PLAY)
            continue;
        char k[8];
        key_text(controls[i].keys[0], k, sizeof k);
        ADD("%s%s", first ? "" : " ", k);
        first = 0;
    }
    ADD(")");
#undef ADD
    return used;
}
