/* SIGINT and SIGTERM ask a run to stop at its next safe point (docs/solver.md, "Stopping a
 * run"): the handler only records the signal; the Newton loop and the increment loop poll it.
 * SA_RESETHAND restores the default action, so a second signal ends the process at once.
 * SA_RESTART keeps system calls (file output) from failing with EINTR. */
#include <signal.h>
#include <string.h>

static volatile sig_atomic_t frix_stop_signal = 0;

static void frix_on_stop_signal(int signal_number) { frix_stop_signal = signal_number; }

void frix_install_stop_handlers_c(void)
{
   struct sigaction action;
   memset(&action, 0, sizeof action);
   action.sa_handler = frix_on_stop_signal;
   sigemptyset(&action.sa_mask);
   action.sa_flags = SA_RESETHAND | SA_RESTART;
   sigaction(SIGINT, &action, NULL);
   sigaction(SIGTERM, &action, NULL);
}

/* The signal received (SIGINT 2, SIGTERM 15), 0 if none. */
int frix_stop_signal_c(void) { return (int)frix_stop_signal; }
