/* psabi_quiet.h - silences gcc's and clang's note that the ABI for
 * passing 32-byte vectors changed (GCC 4.6): the vector helpers of the
 * file that includes this are inlined, so no call passes a vector,
 * whatever the ABI (step_bspline2.c, normals_qr_pivot.c). For the rest of
 * that file. */
#ifndef LAMINA_PSABI_QUIET_H
#define LAMINA_PSABI_QUIET_H

#if defined(__clang__)
#pragma clang diagnostic ignored "-Wunknown-warning-option"
#pragma clang diagnostic ignored "-Wpsabi"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#endif
