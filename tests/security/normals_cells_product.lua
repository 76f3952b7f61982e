-- expect: 2
-- stderr: normals_cells_product\.lua:5: lamina\.normals: 'cells' makes 1000000000 cells, more than the limit of 4000000
-- Issue 18, memory: lamina.normals{cells = {1000, 1000, 1000}} checked each
-- axis, not the product (1e9 cells).
lamina.normals{ points = {{0.2, 0.2, 0.2}, {0.5, 0.5, 0.5}, {0.8, 0.8, 0.8}},
                box = {0, 0, 0, 1, 1, 1},
                cells = {1000, 1000, 1000} }
