/* interrupt.c: SIGINT and SIGTERM during a run. The handler only notes the signal (and says so on
 * stderr, with write(2), which is async-signal-safe); the time loop reads the note after each
 * step (host/loop/loop.c), the case sandbox's count hook every thousand Lua instructions
 * (host/scene/case.c). A second signal while the first is being served exits at once (_exit, 128 +
 * signal), as a user who presses Ctrl-C twice expects. */
#include "interrupt.h"

#include <signal.h>
#include <string.h>
#include <unistd.h>

static volatile sig_atomic_t caught = 0;
static struct sigaction old_int, old_term;
static int active = 0;

static void say(const char *msg)
{
  ssize_t w = write(STDERR_FILENO, msg, strlen(msg));
  (void)w; /* nothing to be done about a failed write in a signal handler */
}

static void on_signal(int sig)
{
  if (caught != 0) {
    say("\nclsph: interrupted again: exiting at once (no checkpoint)\n");
    _exit(128 + sig);
  }
  caught = sig;
  say("\nclsph: interrupted: the step ends, then a checkpoint and summary.json are written "
      "(interrupt again to exit at once)\n");
}

void interrupt_catch(void)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART; /* file and device calls carry on */
  caught = 0;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  active = 1;
}

void interrupt_release(void)
{
  if (!active) return;
  sigaction(SIGINT, &old_int, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  active = 0;
}

int interrupt_signal(void)
{
  return caught;
}

const char *interrupt_name(int sig)
{
  return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
}
