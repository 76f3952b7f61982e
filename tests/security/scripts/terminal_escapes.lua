-- Run by security.terminal_escapes (issue 31 item 8): a script's text with
-- terminal escape sequences (OSC 52 writes the clipboard, OSC 0 the title,
-- CSI 2J clears the screen; CSI as the C1 byte U+009B) through every way
-- it reaches the terminal.
local evil = "a\27]52;c;ZXZpbA==\7b\27]0;owned\7c\27[2Jd\194\155e\r\8\0f\127g"
print("print:", evil, "é€")
io.write("io.write: ", evil, "\n")
lamina.report{ value = evil }
error("error: " .. evil, 0)
