/* warning_queue.h - libverve's log warnings kept for a binding's host to read when it likes.
 *
 * libverve reports a few events through the log hook of verve_set_hooks (a reward clamped to
 * [-1, 1], an agent's RBF budget reached: once per agent each). A scripting host has no C callback
 * of its own, so the Lua module and the Godot plugin install this queue as the hook and hand the
 * messages over on request (verve.warnings() in Lua, VerveAgent.take_warnings() in Godot).
 * Shared by the C bindings; thread-safe (batch workers may warn concurrently). */
#ifndef VERVE_BINDINGS_WARNING_QUEUE_H
#define VERVE_BINDINGS_WARNING_QUEUE_H

#include <stddef.h>

/* The most messages kept between two reads; later ones are counted, not kept. */
#define VW_CAPACITY 64
#define VW_MESSAGE_SIZE 512

/* Installs the queue as libverve's log hook (verve_set_hooks with the C library's allocator), once
 * per process. Returns 1 once installed (now or earlier), 0 when libverve refused: it holds memory
 * (agents exist that this binding did not see created); verve_last_error() says why. */
int vw_install(void);

/* Also hands each warning, as it comes, to echo (NULL: none), outside the queue's lock and on the
 * thread that warns: the Godot plugin prints it in the engine's output. Set it before vw_install. */
void vw_set_echo(void (*echo)(const char* message));

/* Calls each(user, message) for every queued message, oldest first, then empties the queue. When
 * messages were dropped for lack of room, a last one says how many. Returns the number handed over.
 * Called outside the queue's lock, so each may call Verve. */
size_t vw_take(void (*each)(void* user, const char* message), void* user);

#endif
