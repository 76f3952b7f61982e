-- expect: 2
-- stderr: read_csv_outside\.lua:6: lamina\.read_csv: cannot read '\.\./\.\./\.\./etc/passwd\.csv': it resolves to '.*', outside the output root
-- Issue 31 item 7: read_csv's refusals said "cannot write" (it shared the
-- writers' check). Reading is confined as writing is, and says "read"; it
-- neither checks who wrote the file nor notes it as lamina's output.
lamina.read_csv("../../../etc/passwd.csv")
