/* check.h - the smallest test harness: CHECK counts failures, main returns them.
 *
 * Each unit test is one executable; ctest treats a non-zero exit as failure.
 * CHECK_NEAR prints both values so a failing tolerance says by how much. */
#ifndef LAMINA_CHECK_H
#define LAMINA_CHECK_H

#include <math.h>
#include <stdio.h>

static int check_failures;

#define CHECK(cond)                                                         \
    do {                                                                    \
        if (!(cond)) {                                                      \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, \
                    #cond);                                                 \
            check_failures++;                                               \
        }                                                                   \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                               \
    do {                                                                    \
        double ca_ = (a), cb_ = (b), ct_ = (tol);                           \
        if (!(fabs(ca_ - cb_) <= ct_)) {                                    \
            fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s = %.17g, %s = %.17g," \
                    " |diff| = %.3g > %.3g\n", __FILE__, __LINE__, #a, ca_, \
                    #b, cb_, fabs(ca_ - cb_), ct_);                         \
            check_failures++;                                               \
        }                                                                   \
    } while (0)

#define CHECK_DONE()                                                        \
    (check_failures ? (fprintf(stderr, "%d check(s) failed\n",              \
                               check_failures), 1) : 0)

#endif
