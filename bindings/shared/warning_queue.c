/* warning_queue.c - see warning_queue.h. */
#include "warning_queue.h"

#include <stdio.h>
#include <string.h>

#include <verve_c.h>

#if defined(_WIN32)
#  define WIN32_LEAN_AND_MEAN
#  include <windows.h>
static SRWLOCK vw_lock_ = SRWLOCK_INIT;
#  define VW_LOCK() AcquireSRWLockExclusive(&vw_lock_)
#  define VW_UNLOCK() ReleaseSRWLockExclusive(&vw_lock_)
#else
#  include <pthread.h>
static pthread_mutex_t vw_lock_ = PTHREAD_MUTEX_INITIALIZER;
#  define VW_LOCK() pthread_mutex_lock(&vw_lock_)
#  define VW_UNLOCK() pthread_mutex_unlock(&vw_lock_)
#endif

static char vw_messages[VW_CAPACITY][VW_MESSAGE_SIZE];
static size_t vw_first; /* the oldest message not yet handed over */
static size_t vw_count;
static size_t vw_dropped;
static int vw_installed;
static void (*vw_echo)(const char* message);

void vw_set_echo(void (*echo)(const char* message)) { vw_echo = echo; }

static void VERVE_CALL vw_log(void* user, verve_log_level level, const char* message) {
    (void)user;
    (void)level;
    VW_LOCK();
    if (vw_count < VW_CAPACITY) {
        strncpy(vw_messages[vw_count], message ? message : "", VW_MESSAGE_SIZE - 1);
        vw_messages[vw_count][VW_MESSAGE_SIZE - 1] = '\0';
        ++vw_count;
    } else {
        ++vw_dropped;
    }
    VW_UNLOCK();
    if (vw_echo) vw_echo(message ? message : "");
}

int vw_install(void) {
    int done;
    VW_LOCK();
    done = vw_installed;
    VW_UNLOCK();
    if (done) return 1;
    verve_hooks hooks;
    memset(&hooks, 0, sizeof hooks);
    hooks.struct_size = VERVE_HOOKS_SIZE_V1;
    hooks.log_fn = vw_log;
    if (verve_set_hooks(&hooks) != VERVE_OK) return 0;
    VW_LOCK();
    vw_installed = 1;
    VW_UNLOCK();
    return 1;
}

size_t vw_take(void (*each)(void* user, const char* message), void* user) {
    /* One message at a time, copied out under the lock and handed over outside it. */
    char message[VW_MESSAGE_SIZE];
    size_t n = 0;
    for (;;) {
        int have = 1;
        VW_LOCK();
        if (vw_first < vw_count) {
            memcpy(message, vw_messages[vw_first++], VW_MESSAGE_SIZE);
        } else if (vw_dropped > 0) {
            snprintf(message, sizeof message, "%lu more warnings were dropped (at most %d are kept between reads)",
                     (unsigned long)vw_dropped, VW_CAPACITY);
            vw_dropped = 0;
        } else {
            have = 0;
        }
        if (vw_first == vw_count) vw_first = vw_count = 0;
        VW_UNLOCK();
        if (!have) return n;
        each(user, message);
        ++n;
    }
}
