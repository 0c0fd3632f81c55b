/* VERIFY vs ASSERT.
 * RCFW_VERIFY: bad *external* input (bus bytes, host values, FRAM contents). Not a bug:
 *   count it and return an error value; never trap.
 * RCFW_ASSERT: an internal invariant; failing means a firmware bug. Calls the port's
 *   rcfw_assert_failed(line), which does not return (host: abort; target: safe stop + reset). */
#ifndef RCFW_VERIFY_H
#define RCFW_VERIFY_H

void rcfw_assert_failed(int line);

#define RCFW_VERIFY(cond, counter, retval) \
    do {                                   \
        if (!(cond)) {                     \
            (counter)++;                   \
            return retval;                 \
        }                                  \
    } while (0)

#define RCFW_ASSERT(cond)                 \
    do {                                  \
        if (!(cond)) {                    \
            rcfw_assert_failed(__LINE__); \
        }                                 \
    } while (0)

#endif
