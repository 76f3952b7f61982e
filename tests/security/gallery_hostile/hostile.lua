-- title: Hostile <img src=x onerror=alert(1)> title
-- source: <script>alert(2)</script> & r <= 0.1
-- look: <iframe src=javascript:alert(3)></iframe>
-- Run by security.gallery_markdown_html (issue 31 item 8): the header's
-- text and a reported string go into the figure's README.md, which
-- Markdown viewers render with its raw HTML.
local out = lamina.param("out", "out/security/hostile")
local sim = lamina.sim{ dt = 1e-3 }
sim:frame{ file = out .. "/hostile.png", width = 32, height = 32 }
lamina.report{ note = "<svg onload=alert(4)>", ["<b>name</b>"] = 1 }
