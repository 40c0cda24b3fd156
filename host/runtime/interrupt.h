/* interrupt.h: SIGINT and SIGTERM during `clsph run`: the first is noted, and the run stops at
 * the next safe point (the time loop after the step it interrupts, with a checkpoint and the
 * summary; the case script at its next instructions); the second exits at once. */
#ifndef CLSPH_INTERRUPT_H
#define CLSPH_INTERRUPT_H

/** @brief Catch SIGINT and SIGTERM (until interrupt_release). */
void interrupt_catch(void);
/** @brief Give SIGINT and SIGTERM back their earlier handlers. */
void interrupt_release(void);
/** @brief The signal caught since interrupt_catch (SIGINT or SIGTERM), or 0. */
int interrupt_signal(void);
/** @brief "SIGINT", "SIGTERM" or "a signal". */
const char *interrupt_name(int sig);

#endif /* CLSPH_INTERRUPT_H */
