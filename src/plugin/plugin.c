/* Loading student plugins without running their code here: the plugin's
 * host (host_link.c), jailed, dlopens the file and calls sw_plugin_info()
 * under the watchdog, and sends back a copy of what it found; the parent
 * terminates every string itself and checks every field before anything
 * is registered. The host stays for the plugin's runs. Invariant: every
 * byte a plugin chose reaches a message only through sw_escape
 * (util/escape.h), and no length it sent is used. */
#include "plugin/plugin.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "plugin/plugin_box.h"
#include "plugin/sandbox.h"
#include "util/utf8.h"

/* Length of the UTF-8 sequence at s (avail bytes) that is a printable
 * character: well formed (no overlong form, surrogate or code point past
 * U+10FFFF), no C0/C1 control, no DEL; 0 when it is none. Bidirectional
 * and zero-width characters are printable here and escaped wherever a
 * label is shown (util/escape.h). */
static int printable_char(const unsigned char *s, size_t avail)
{
    size_t len;
    uint32_t cp;
    if (sw_utf8_check(s, avail, &len, &cp) != SW_UTF8_OK)
        return 0;
    if (cp < 0x20 || cp == 0x7f || (cp >= 0x80 && cp < 0xa0))
        return 0;
    return (int)len;
}

int sw_plugin_name_ok(const char *name, char *why, size_t whylen)
{
    size_t len = strlen(name);
    if (len == 0 || len > SW_PLUGIN_NAME_MAX) {
        snprintf(why, whylen, "a name has 1 to %d characters (this one has %zu)", SW_PLUGIN_NAME_MAX, len);
        return 0;
    }
    if (!isalnum((unsigned char)name[0])) {
        snprintf(why, whylen, "a name starts with a letter or a digit");
        return 0;
    }
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)name[i];
        if (!isalnum(c) && !strchr("._+-", c)) {
            snprintf(why, whylen, "character %zu is not allowed (a name takes letters, digits, "
                     "'.', '_', '+' and '-')", i + 1);
            return 0;
        }
    }
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (!(m->flags & SW_PLUGIN) && strcasecmp(m->name, name) == 0) {
            snprintf(why, whylen, "it shadows the built-in method '%s'", m->name);
            return 0;
        }
    }
    return 1;
}

int sw_plugin_label_ok(const char *label, char *why, size_t whylen)
{
    size_t len = strlen(label);
    if (len == 0 || len > SW_PLUGIN_LABEL_MAX) {
        snprintf(why, whylen, "a label has 1 to %d bytes (this one has %zu)", SW_PLUGIN_LABEL_MAX, len);
        return 0;
    }
    if (label[0] == ' ' || label[len - 1] == ' ') {
        snprintf(why, whylen, "a label does not start or end with a blank");
        return 0;
    }
    for (size_t i = 0; i < len;) {
        int n = printable_char((const unsigned char *)label + i, len - i);
        if (n == 0) {
            snprintf(why, whylen, "byte %zu is a control character or not UTF-8 (a label is "
                     "printable text)", i + 1);
            return 0;
        }
        i += (size_t)n;
    }
    return 1;
}

/* Every field of what loading found checked; 0, or SW_EINVAL with why. */
static int check_reply(const sw_host_info *r, const char *shown, char *err, size_t errlen)
{
    char esc[200];
    switch (r->stage) {
    case SW_HOST_STAGE_DLOPEN: {
        /* the loader names the host's copy ("./plugin.so: ..."); the message names the file already */
        const char *why_dl = r->dlerr;
        size_t at = strcspn(why_dl, ":");
        if (why_dl[at] == ':' && at < 64 && strstr(why_dl, "plugin.so") && strstr(why_dl, "plugin.so") < why_dl + at)
            why_dl += at + (why_dl[at + 1] == ' ' ? 2 : 1);
        sw_escape(why_dl, 160, esc, sizeof esc);
        snprintf(err, errlen, "'%s' could not be loaded: %s", shown, esc);
        return SW_EINVAL;
    }
    case SW_HOST_STAGE_SYMBOL:
        snprintf(err, errlen, "'%s' has no sw_plugin_info symbol; a plugin must define "
                 "const sw_plugin *sw_plugin_info(void)", shown);
        return SW_EINVAL;
    case SW_HOST_STAGE_NULL:
        snprintf(err, errlen, "'%s': sw_plugin_info() returned NULL; it must return the "
                 "address of a static sw_plugin", shown);
        return SW_EINVAL;
    case SW_HOST_STAGE_OK:
        break;
    default:
        snprintf(err, errlen, "'%s': its loader sent a reply it could not have sent", shown);
        return SW_EINVAL;
    }
    if (r->abi != SW_PLUGIN_ABI) { /* (1: sw_ode had the engine's fast-path fields; they moved) */
        snprintf(err, errlen, "'%s' was built for plugin interface %d; this stepwise needs "
                 "%d: rebuild it from its .c (give stepwise the .c file, or see docs/plugins.md for "
                 "the cc line)", shown, r->abi, SW_PLUGIN_ABI);
        return SW_EINVAL;
    }
    if (!r->name[0] || !r->has_step || r->work_vectors < 0 || r->work_vectors > 64) {
        snprintf(err, errlen, "'%s': sw_plugin_info() must give a name, a step function "
                 "and 0..64 work vectors", shown);
        return SW_EINVAL;
    }
    return SW_OK;
}

static int any_name;

void sw_plugin_set_any_name(int on) { any_name = on != 0; }

/* The name and the label checked: SW_OK, or SW_EINVAL with err; where any
 * name goes (grading), one not allowed is replaced and renamed says why. */
static int name_and_label(sw_host_info *r, const char *shown, char *renamed, size_t renamedlen, char *err,
                          size_t errlen)
{
    char why[SW_ERRLEN], esc[200];
    renamed[0] = '\0';
    sw_escape(r->name, SW_PLUGIN_NAME_MAX + 8, esc, sizeof esc);
    int long_name = strlen(r->name) >= sizeof r->name - 1;
    if (long_name || !sw_plugin_name_ok(r->name, why, sizeof why)) {
        if (long_name)
            snprintf(why, sizeof why, "a name has 1 to %d characters", SW_PLUGIN_NAME_MAX);
        if (!any_name) {
            snprintf(err, errlen, "'%s': the name '%s' is not allowed: %s", shown, esc, why);
            return SW_EINVAL;
        }
        snprintf(renamed, renamedlen, "its name '%.60s' is not allowed (%.120s): graded as '%s'", esc, why,
                 SW_PLUGIN_GRADED_NAME);
        snprintf(r->name, sizeof r->name, "%s", SW_PLUGIN_GRADED_NAME);
    }
    const char *label = r->has_label ? r->label : r->name;
    int long_label = strlen(label) >= sizeof r->label - 1;
    if (r->has_label && (long_label || !sw_plugin_label_ok(label, why, sizeof why))) {
        if (long_label)
            snprintf(why, sizeof why, "a label has 1 to %d bytes", SW_PLUGIN_LABEL_MAX);
        sw_escape(label, 60, esc, sizeof esc);
        if (!any_name) {
            snprintf(err, errlen, "'%s': the label '%s' is not allowed: %s", shown, esc, why);
            return SW_EINVAL;
        }
        size_t at = strlen(renamed);
        snprintf(renamed + at, renamedlen - at, "%sits label '%.60s' is not allowed (%.120s): shown as its name",
                 at ? "; " : "", esc, why);
        r->has_label = 0;
    }
    return SW_OK;
}

void sw_plugin_hosts_end(void)
{
    for (int i = 0; i < SW_PLUGIN_MAX; i++) {
        sw_plugin_entry *e = sw_plugin_entry_at(i);
        if (e)
            sw_host_stop(e);
    }
}

void sw_plugin_grader_runs(int on)
{
    if ((on != 0) == sw_plugin_grader_open())
        return;
    sw_plugin_hosts_end(); /* the closing account's hosts, reaped: their time is counted */
    sw_plugin_account(on);
}

/* At exit, every plugin's host ends (and a UID jail's directory with it). */
static void stop_hosts(void) { sw_plugin_hosts_end(); }

int sw_plugin_load(const char *path, const char *shown_as, const sw_integrator **out, char *err,
                   size_t errlen)
{
    static int registered;
    if (!registered && atexit(stop_hosts) == 0)
        registered = 1;
    char shown[200], why[SW_ERRLEN];
    sw_escape(shown_as ? shown_as : path, 120, shown, sizeof shown);
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "'%s': no such file (give the path to a .so built from "
                 "examples/euler_plugin.c)", shown);
        return SW_EINVAL;
    }
    sw_plugin_entry *e = sw_plugin_entry_next();
    if (!e) {
        snprintf(err, errlen, "at most %d plugins can be loaded", SW_PLUGIN_MAX);
        return SW_EINVAL;
    }
    memset(e, 0, sizeof *e);
    e->fd = -1;
    if (!realpath(path, e->path)) {
        snprintf(err, errlen, "'%s': %s", shown, strerror(errno));
        return SW_EIO;
    }
    /* The file as it is now is what every child loads (a rebuild that
     * replaces it does not change a plugin under way). */
    e->fd = open(e->path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    struct stat fst;
    if (e->fd < 0 || fstat(e->fd, &fst) != 0 || !S_ISREG(fst.st_mode)) {
        snprintf(err, errlen, "'%s': %s", shown, e->fd < 0 ? strerror(errno) : "not a regular file");
        if (e->fd >= 0)
            close(e->fd);
        return SW_EINVAL;
    }
    /* Loaded in its host, which stays for the runs to come. */
    snprintf(e->shown, sizeof e->shown, "%s", shown);
    sw_host_info r;
    int rc = sw_host_start(e, &r, err, errlen);
    if (rc == SW_OK)
        rc = check_reply(&r, shown, err, errlen);
    if (rc == SW_OK) {
        snprintf(e->own_name, sizeof e->own_name, "%s", r.name);
        rc = name_and_label(&r, shown, e->renamed, sizeof e->renamed, err, errlen);
    }
    if (rc != SW_OK) {
        sw_host_stop(e);
        close(e->fd);
        return rc;
    }
    const char *label = r.has_label ? r.label : r.name;
    memcpy(e->name, r.name, strlen(r.name) + 1);          /* checked: at most 40 bytes */
    memcpy(e->label, label, strlen(label) + 1);           /* checked: at most 80 bytes */
    e->work_vectors = r.work_vectors;
    sw_integrator m = { .name = e->name, .label = e->label, .order = r.order, .evals = r.evals,
                        .flags = SW_PLUGIN | SW_EXPLICIT, .stability = NAN,
                        .work_vectors = r.work_vectors, .step = sw_plugin_step,
                        .summary = "student plugin (run in its own sandboxed process)",
                        .no_lecture = "a plugin's stages run in its sandbox" };
    if (sw_integrator_register(&m, why, sizeof why) != SW_OK) {
        sw_host_stop(e);
        close(e->fd);
        snprintf(err, errlen, "'%s': %s", shown, why);
        return SW_EINVAL;
    }
    e->method = sw_integrator_find(e->name);
    sw_plugin_entry_commit();
    if (out)
        *out = e->method;
    return SW_OK;
}

sw_plugin_fault sw_plugin_failed(sw_sim *s)
{
    if (!s->blown || !(s->method->flags & SW_PLUGIN) || !s->stepper)
        return SW_PF_NONE;
    return sw_plugin_box_fault(s->stepper, s->blow_step, s->blow_reason, sizeof s->blow_reason);
}

const char *sw_plugin_renamed(const sw_integrator *m)
{
    sw_plugin_entry *e = sw_plugin_entry_for(m);
    return e && e->renamed[0] ? e->renamed : NULL;
}

sw_plugin_fault sw_plugin_last_failure(const sw_integrator *m, char *buf, size_t len)
{
    sw_plugin_entry *e = sw_plugin_entry_for(m);
    if (!e || e->last_fault == SW_PF_NONE)
        return SW_PF_NONE;
    snprintf(buf, len, "%s", e->last_failure);
    return e->last_fault;
}

long long sw_plugin_printed(const sw_integrator *m)
{
    sw_plugin_entry *e = sw_plugin_entry_for(m);
    if (!e)
        return -1;
    const sw_host_link *h = &e->host;
    return e->printed_before + (h->dying && h->printed > h->printed_end ? h->printed : h->printed_end);
}

void sw_plugin_forgive(const sw_integrator *m)
{
    sw_plugin_entry *e = sw_plugin_entry_for(m);
    if (e && !e->disabled) {
        e->last_fault = SW_PF_NONE;
        e->last_failure[0] = '\0';
    }
}

void sw_plugin_disable(const sw_integrator *m, const char *why)
{
    sw_plugin_entry *e = sw_plugin_entry_for(m);
    if (!e)
        return;
    e->disabled = 1;
    snprintf(e->disabled_why, sizeof e->disabled_why, "%s", why);
    sw_integrator_disable(m, why);
}
