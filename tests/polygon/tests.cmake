# Polygon shapes, overlap kernels and the area-based contact law (owner: poly).
pl_add_c_test(test_polygon_geometry SOURCES polygon/test_polygon_geometry.c LABEL polygon)
pl_add_c_test(test_polygon_contact SOURCES polygon/test_polygon_contact.c LABEL polygon)
pl_add_c_test(test_polygon_incline SOURCES polygon/test_polygon_incline.c LABEL polygon)
pl_add_c_test(test_polygon_determinism SOURCES polygon/test_polygon_determinism.c LABEL polygon)
pl_add_c_test(test_polygon_heap SOURCES polygon/test_polygon_heap.c LABEL polygon)
