# tests/out_fixtures.cmake - what the security and EGL tests expect to find in
# their working folders: run as the test `fixtures.out` before them (and not
# only at configure time), so a build tree whose tests/out was cleared runs
# the same as a fresh one.  Called with -DOUT=<build>/tests/out.
file(MAKE_DIRECTORY ${OUT}/security/root ${OUT}/egl_cannot_start)
# a link leading out of the output root
file(CREATE_LINK / ${OUT}/security/to_slash SYMBOLIC)
# a file lamina did not write, and a link to it (issue 31, out_not_ours)
file(WRITE ${OUT}/security/theirs/conftest.py "print('not lamina')\n")
file(CREATE_LINK conftest.py ${OUT}/security/theirs/link.csv SYMBOLIC)
# (The output list, tests/.lamina-outputs, is left alone: other tests append
# to it while this runs. conftest.py is made here before every run, so no
# run finds it missing and lists it as lamina's.)
