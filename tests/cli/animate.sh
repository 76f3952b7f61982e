#!/bin/sh
# lamina animate writes only the file it was asked for (issue 35 item 5):
# an MP4 that cannot be made (no ffmpeg) is exit status 2 and nothing
# written - an APNG beside it stays byte for byte; a format lamina does not
# make, an output that is a frame, and a default FOLDER.apng that lamina did
# not write are refused the same way; the asked APNG is written, and the
# default one replaces lamina's own earlier animation.
. "$(dirname "$0")/lib.sh"
"$LAMINA" run "$SRC/frames.lua" --set out=r > run.txt 2>&1 || { show run.txt; exit 1; }
n=$(ls r/frames | grep -c '\.png$')
[ "$n" -eq 4 ] || { echo "FAIL: $n frames, expected 4"; fail=1; }

# expect2 NAME PATTERN ARGS...: exit status 2 and the message
expect2() {
  name=$1; pat=$2; shift 2
  PATH=/nonexistent "$LAMINA" animate "$@" > "$name.txt" 2>&1
  st=$?
  [ $st -eq 2 ] || { echo "FAIL: $name: exit status $st, expected 2"; fail=1; show "$name.txt"; }
  check "$name.txt" "$pat"
}

# an APNG the user made earlier, and an MP4 asked for without ffmpeg
"$LAMINA" animate r/frames --out movie.apng --quiet 2> a.txt || { echo "FAIL: movie.apng"; show a.txt; fail=1; }
cp movie.apng before.apng
expect2 no_ffmpeg "cannot make the MP4 'movie.mp4': ffmpeg is not installed .*nothing written" r/frames --out movie.mp4
cmp -s movie.apng before.apng || { echo "FAIL: movie.apng changed"; fail=1; }
[ ! -e movie.mp4 ] || { echo "FAIL: movie.mp4 written"; fail=1; }

# a format lamina does not make
expect2 gif "cannot make 'movie.gif'.*nothing written" r/frames --out movie.gif
[ ! -e movie.gif ] || { echo "FAIL: movie.gif written"; fail=1; }

# the output is a frame
cp r/frames/frame_0001.png keep.png
expect2 is_frame "is one of the frames" r/frames/frame_0001.png r/frames/frame_0002.png --out r/frames/frame_0001.png
cmp -s keep.png r/frames/frame_0001.png || { echo "FAIL: a frame was replaced"; fail=1; }

# the default name (r/frames.apng): not over a file lamina did not write ...
echo "my notes" > r/frames.apng
expect2 default_foreign "'r/frames.apng' exists and is not an animation lamina wrote" r/frames
check r/frames.apng "^my notes$"
# ... but over its own earlier animation, and over anything when named
rm r/frames.apng
"$LAMINA" animate r/frames 2> d1.txt || { echo "FAIL: default animation"; show d1.txt; fail=1; }
check d1.txt "4 frames \(48x48, 10 fps\) -> r/frames.apng \(APNG"
"$LAMINA" animate r/frames --fps 5 2> d2.txt || { echo "FAIL: default animation again"; show d2.txt; fail=1; }
check d2.txt "4 frames \(48x48, 5 fps\) -> r/frames.apng"
echo "my notes" > named.png
"$LAMINA" animate r/frames --out named.png 2> d3.txt || { echo "FAIL: named output"; show d3.txt; fail=1; }
check_not named.png "^my notes$"
exit $fail
