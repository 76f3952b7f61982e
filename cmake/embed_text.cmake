# embed_text.cmake - turns a text file into a C string at build time:
#   cmake -DIN=page.html -DOUT=page.c -DNAME=symbol -P embed_text.cmake
# The file must be ASCII (no byte above 0x7f): the page `lamina serve`
# embeds says so in its header and carries no encoding surprises.
file(READ "${IN}" hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," body "${hex}")
if(body MATCHES "0x[89a-f]")
  message(FATAL_ERROR "${IN}: holds a byte that is not ASCII")
endif()
string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" body "${body}")
file(WRITE "${OUT}.tmp"
  "/* generated from ${IN} by cmake/embed_text.cmake: do not edit */\n"
  "#include <stddef.h>\n"
  "const char ${NAME}[] = {\n${body}0x00};\n"
  "const size_t ${NAME}_len = sizeof ${NAME} - 1;\n")
file(RENAME "${OUT}.tmp" "${OUT}")
