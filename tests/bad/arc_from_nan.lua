-- expect: 2
-- stderr: arc_from_nan\.lua:5: lamina\.arc: .center., .from. and .to. must be finite \(got from = -?nan, to = 360\.0\)
-- Issue 31 item 7: NaN passed the arc's span check (every comparison
-- false) and made a curve of NaN points.
lamina.arc{ center = {0.5, 0.5}, radius = 0.2, from = 0/0 }
