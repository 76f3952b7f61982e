-- expect: 2
-- stderr: region_infinite\.lua:6: lamina\.disk: .radius. must be a finite positive number and .center. finite \(got radius inf at \{0\.5, 0\.5\}\)
-- Issue 31 item 7: an infinite disk or rectangle was accepted (its area,
-- for fill = "clipped", is inf). Large finite ones fill the domain.
assert(not pcall(lamina.rect, { x0 = 0, y0 = 0, x1 = 1/0, y1 = 1 }))
lamina.disk{ center = {0.5, 0.5}, radius = 1/0 }
