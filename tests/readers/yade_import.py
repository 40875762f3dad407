# Imports a packing written by frontpack (Yade text, .txt) into a Yade scene, headless:
#
#     frontpack fill shapes/l_shape.wkt --radius uniform:0.01,0.05 -o packing.txt   (or write_file)
#     yade -n -x tests/readers/yade_import.py packing.txt
#
# ymport.textExt (format x_y_z_r, its default) and pack.SpherePack().load() both read the file's
# "x y z r" lines, one per sphere; frontpack's disks
# come in as spheres in the plane z = 0, with exactly the written radii and centres. For a 2D
# simulation, constrain the motion to the plane yourself (e.g. block z translation and x/y
# rotation: b.state.blockedDOFs = 'zXY').
#
# For the tests (tests/readers/check_readers.py), it prints every body as
# "FRONTPACK_BODY x y z r" with repr(), which round-trips doubles exactly.
import sys

from yade import O, pack, ymport

spheres = ymport.textExt(sys.argv[1], format='x_y_z_r')
O.bodies.append(spheres)
print("FRONTPACK_COUNT %d" % len(O.bodies))
for b in O.bodies:
    p = b.state.pos
    print("FRONTPACK_BODY %r %r %r %r" % (float(p[0]), float(p[1]), float(p[2]), float(b.shape.radius)))
sp = pack.SpherePack()
sp.load(sys.argv[1])
for centre, radius in sp:
    print("FRONTPACK_SPHEREPACK %r %r %r %r" % (float(centre[0]), float(centre[1]), float(centre[2]), float(radius)))
