/* libverve's log warnings for the JavaScript binding: the bindings' shared queue
 * (bindings/shared/warning_queue.c) installed as the log hook when the module loads, and read by
 * Verve.takeWarnings() (src/index.js) as one string, the messages one per line. */
#include <string.h>

#include "warning_queue.h"

/* The queue's most messages (and the line that counts the dropped ones), a newline after each. */
static char vww_text[(VW_CAPACITY + 1) * VW_MESSAGE_SIZE + 1];
static size_t vww_length;

static void vww_append(void* user, const char* message) {
    (void)user;
    size_t n = strlen(message);
    if (vww_length + n + 2 > sizeof vww_text) return; /* cannot happen: the queue holds fewer */
    memcpy(vww_text + vww_length, message, n);
    vww_length += n;
    vww_text[vww_length++] = '\n';
}

/* 1 once the queue is libverve's log hook; 0 when libverve refused (it already holds memory). */
int verve_web_install_warnings(void) { return vw_install(); }

/* The warnings since the previous call, oldest first, each ending in a newline; "" for none. */
const char* verve_web_take_warnings(void) {
    vww_length = 0;
    vw_take(vww_append, NULL);
    vww_text[vww_length] = '\0';
    return vww_text;
}
