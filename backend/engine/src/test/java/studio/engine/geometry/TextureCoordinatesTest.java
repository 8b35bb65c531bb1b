package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;

/** Each shape's (u, v) at a hit, and dp/du, dp/dv agreeing with how (u, v) change across the surface. */
class TextureCoordinatesTest {

    private static final double EPS = 1e-9;

    private static TextureCoordinates at(Shape shape, Ray ray) {
        Hit hit = new Hit();
        assertTrue(shape.intersect(ray, Double.POSITIVE_INFINITY, hit), "the ray should hit " + shape);
        TextureCoordinates c = new TextureCoordinates();
        shape.textureCoordinates(hit, c);
        return c;
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(ox, oy, oz, dx, dy, dz);
    }

    @Test
    void sphereIsLongitudeAndLatitudeAsThreeJsLaysThemOut() {
        Sphere s = new Sphere(new Vec3(1, 2, 3), 2);
        TextureCoordinates minusX = at(s, ray(-10, 2, 3, 1, 0, 0));
        assertEquals(0, minusX.u, EPS);
        assertEquals(0.5, minusX.v, EPS);
        TextureCoordinates plusZ = at(s, ray(1, 2, 10, 0, 0, -1));
        assertEquals(0.25, plusZ.u, EPS);
        TextureCoordinates top = at(s, ray(1.000001, 10, 3, 0, -1, 0));
        assertEquals(1, top.v, 1e-6);
        assertEquals(2 * Math.PI * 2, minusX.metresU, EPS);
        assertTrue(minusX.wrapsU);
        // three.js SphereGeometry: x = -cos(2 pi u) sin(theta), z = sin(2 pi u) sin(theta), theta = pi (1 - v)
        Random random = new Random(1);
        for (int i = 0; i < 100; i++) {
            double y = random.nextDouble() * 1.8 - 0.9, a = random.nextDouble() * 2 * Math.PI;
            double r = Math.sqrt(1 - y * y);
            Vec3 n = new Vec3(r * Math.cos(a), y, r * Math.sin(a));
            Vec3 p = new Vec3(1, 2, 3).plus(n.times(2));
            Vec3 o = p.plus(n.times(5));
            TextureCoordinates c = at(s, ray(o.x(), o.y(), o.z(), -n.x(), -n.y(), -n.z()));
            double theta = Math.PI * (1 - c.v);
            assertEquals(n.x(), -Math.cos(2 * Math.PI * c.u) * Math.sin(theta), 1e-9);
            assertEquals(n.z(), Math.sin(2 * Math.PI * c.u) * Math.sin(theta), 1e-9);
            assertEquals(n.y(), Math.cos(theta), 1e-9);
        }
    }

    @Test
    void aFloorIsMetresAlongXAndMinusZ() {
        Plane floor = new Plane(new Vec3(0, 1, 0), new Vec3(0, 2, 0));
        TextureCoordinates c = at(floor, ray(3, 5, -7, 0, -1, 0));
        assertEquals(3, c.u, EPS);
        assertEquals(7, c.v, EPS);
        assertEquals(1, c.dpdux, EPS);
        assertEquals(-1, c.dpdvz, EPS);
    }

    @Test
    void aPlanesFrameIsOrthonormalWhateverItsNormal() {
        Random random = new Random(2);
        for (int i = 0; i < 200; i++) {
            Vec3 n = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).normalized();
            Plane plane = new Plane(Vec3.ZERO, n);
            Vec3 o = n.times(3);
            TextureCoordinates c = at(plane, ray(o.x(), o.y(), o.z(), -n.x(), -n.y(), -n.z()));
            Vec3 t = new Vec3(c.dpdux, c.dpduy, c.dpduz), b = new Vec3(c.dpdvx, c.dpdvy, c.dpdvz);
            assertEquals(1, t.length(), 1e-9);
            assertEquals(1, b.length(), 1e-9);
            assertEquals(0, t.dot(b), 1e-9);
            assertEquals(0, t.dot(n), 1e-9);
        }
    }

    @Test
    void eachBoxFaceRunsFromZeroToOne() {
        Box box = new Box(new Vec3(1, 1, 1), new Vec3(2, 4, 6), new Vec3(0, 30, 0));
        double[][] directions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        for (double[] d : directions) {
            // a ray from outside through the face's centre, in the box's frame turned to the world
            studio.engine.math.Rotation r = studio.engine.math.Rotation.fromEulerDegrees(new Vec3(0, 30, 0));
            Vec3 n = r.apply(new Vec3(d[0], d[1], d[2]));
            Vec3 o = new Vec3(1, 1, 1).plus(n.times(10));
            TextureCoordinates c = at(box, ray(o.x(), o.y(), o.z(), -n.x(), -n.y(), -n.z()));
            assertEquals(0.5, c.u, 1e-9);
            assertEquals(0.5, c.v, 1e-9);
            // dp/du x dp/dv points out of the face: u right and v up seen from outside
            Vec3 t = new Vec3(c.dpdux, c.dpduy, c.dpduz), b = new Vec3(c.dpdvx, c.dpdvy, c.dpdvz);
            assertTrue(t.cross(b).dot(n) > 0, "face " + n);
        }
        TextureCoordinates corner = at(new Box(Vec3.ZERO, new Vec3(2, 2, 2)), ray(-0.999999, -0.999999, 5, 0, 0, -1));
        assertEquals(0, corner.u, 1e-6);
        assertEquals(0, corner.v, 1e-6);
        assertEquals(2, corner.metresU, EPS);
    }

    @Test
    void aMeshInterpolatesItsObjTextureCoordinates() {
        MeshData data = ObjReader.parse("v 0 0 0\nv 2 0 0\nv 0 2 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
        TriangleMesh mesh = new TriangleMesh(data);
        assertTrue(mesh.hasUvs());
        TextureCoordinates c = at(mesh, ray(0.5, 1, 5, 0, 0, -1));
        assertEquals(0.25, c.u, 1e-12);
        assertEquals(0.5, c.v, 1e-12);
        assertEquals(2, c.dpdux, 1e-12);
        assertEquals(2, c.dpdvy, 1e-12);
    }

    @Test
    void aMeshWithoutTextureCoordinatesKeepsNoArrayForThem() {
        MeshData data = ObjReader.parse("v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
        assertNull(data.uvs());
        TextureCoordinates c = at(new TriangleMesh(data), ray(0.5, 1, 5, 0, 0, -1));
        assertEquals(0.25, c.u, 1e-12); // the barycentrics
        assertEquals(0.5, c.v, 1e-12);
    }

    @Test
    void objVerticesSplitWhereTheirTextureCoordinatesDiffer() {
        // two triangles sharing an edge whose vertices carry different UVs in each (a seam)
        MeshData data = ObjReader.parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\n"
                + "f 1/1 2/2 3/3\nf 1/4 3/3 4/3\n");
        assertEquals(5, data.vertexCount());
        assertEquals(2 * 5, data.uvs().length);
    }
}
