"""png_text.py - the text chunks of a PNG (tEXt, zTXt, iTXt) as a dict: what
lamina writes beside the pixels (Software, Title, lamina:layers; src/lua/
l_frame.c), read by the checks in tests/visual and tests/cli."""
import struct
import zlib

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


def png_texts(path):
    """The tEXt / zTXt / iTXt chunks of a PNG, as a dict."""
    out = {}
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(PNG_MAGIC):
        raise ValueError(f"{path}: not a PNG")
    at = len(PNG_MAGIC)
    while at + 8 <= len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        kind = data[at + 4:at + 8]
        body = data[at + 8:at + 8 + length]
        at += 12 + length
        if kind == b"tEXt":
            key, _, value = body.partition(b"\0")
            out[key.decode("latin-1")] = value.decode("latin-1")
        elif kind == b"zTXt":
            key, _, rest = body.partition(b"\0")
            out[key.decode("latin-1")] = zlib.decompress(rest[1:]).decode("latin-1")
        elif kind == b"iTXt":
            key, _, rest = body.partition(b"\0")
            compressed = rest[0]
            rest = rest[2:]
            _, _, rest = rest.partition(b"\0")    # language
            _, _, text = rest.partition(b"\0")    # translated keyword
            out[key.decode("utf-8")] = (zlib.decompress(text) if compressed else text).decode("utf-8")
        elif kind == b"IEND":
            break
    return out
