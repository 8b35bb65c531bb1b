package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.geometry.GeometryAssertions.assertVec;
import static studio.engine.geometry.GeometryAssertions.randomUnit;
import static studio.engine.geometry.GeometryAssertions.uniform;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import studio.engine.camera.Camera;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;
import studio.engine.memory.CountingGate;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.MeshShapes;

/** Watertight ray/triangle hits, the mesh's BVH against testing every triangle, and the mesh's placement. */
class TriangleMeshTest {

    private static MeshData triangles(double... xyz) {
        int[] indices = new int[xyz.length / 3];
        for (int i = 0; i < indices.length; i++) {
            indices[i] = i;
        }
        return new MeshData(xyz, indices, null);
    }

    @Test
    @DisplayName("NUM-06a: a triangle with a flat box renders the same with and without the BVH, and is not culled")
    void flatBoxedTriangleNum06aIsHitTheSameWithAndWithoutTheBvh() {
        TriangleMesh mesh = new TriangleMesh(triangles(-1, -1, -5, 1, -1, -5, 0, 1, -5));
        EachTriangle withoutBvh = new EachTriangle(mesh);
        Hit viaBvh = new Hit(), direct = new Hit();
        int hits = 0;
        for (int i = 0; i <= 20; i++) {
            for (int j = 0; j <= 20; j++) {
                Ray ray = new Ray(0, 0, 0, -0.15 + 0.015 * i, -0.15 + 0.015 * j, -1);
                boolean a = mesh.intersect(ray, Double.POSITIVE_INFINITY, viaBvh);
                boolean b = withoutBvh.intersect(ray, Double.POSITIVE_INFINITY, direct);
                assertEquals(b, a, ray.toString());
                if (a) {
                    hits++;
                    assertEquals(direct.t, viaBvh.t, 0.0);
                }
            }
        }
        assertTrue(hits > 0, "hits on the 441-ray grid");
        // A 64x64 image of it through a camera: identical coverage, and more than 0 pixels.
        Camera camera = new Camera(Vec3.ZERO, new Vec3(0, 0, -5), new Vec3(0, 1, 0), 30);
        int covered = 0;
        for (int y = 0; y < 64; y++) {
            for (int x = 0; x < 64; x++) {
                Ray ray = camera.ray(2 * (x + 0.5) / 64 - 1, 1 - 2 * (y + 0.5) / 64, 1.0);
                boolean a = mesh.intersect(ray, Double.POSITIVE_INFINITY, viaBvh);
                assertEquals(withoutBvh.intersect(ray, Double.POSITIVE_INFINITY, direct), a);
                covered += a ? 1 : 0;
            }
        }
        assertTrue(covered > 0, "pixels covered");
    }

    @Test
    @DisplayName("NUM-08: 200000 rays at an edge shared by two triangles all hit one of them (Moller-Trumbore cracks lose 13 %)")
    void raysThroughASharedEdgeNum08NeverSlipThroughACrack() {
        double[] a = {-1.1, -0.9, -5.3}, b = {1.3, -1.05, -4.7}, c = {1.05, 1.2, -5.1}, d = {-0.95, 1.1, -4.9};
        MeshData quad = new MeshData(new double[] {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]},
                new int[] {0, 1, 2, 0, 2, 3}, null);
        TriangleMesh mesh = new TriangleMesh(quad);
        EachTriangle withoutBvh = new EachTriangle(mesh);
        double ox = 0.1, oy = 0.2, oz = 0.3;
        int n = 200_000, misses = 0, missesWithoutBvh = 0;
        Hit hit = new Hit();
        for (int k = 0; k < n; k++) {
            double s = 0.001 + 0.998 * (k + 0.5) / n;
            double tx = a[0] + s * (c[0] - a[0]), ty = a[1] + s * (c[1] - a[1]), tz = a[2] + s * (c[2] - a[2]);
            Ray ray = new Ray(ox, oy, oz, tx - ox, ty - oy, tz - oz);
            if (!mesh.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                misses++;
            }
            if (!withoutBvh.intersect(ray, Double.POSITIVE_INFINITY, hit)) {
                missesWithoutBvh++;
            }
            if (!mesh.occluded(ray, Double.POSITIVE_INFINITY)) {
                misses++;
            }
        }
        assertEquals(0, misses, "rays through the shared edge that missed both triangles");
        assertEquals(0, missesWithoutBvh);
    }

    @Test
    void bvhFindsTheSameNearestHitAsTestingEveryTriangleInARandomSoup() {
        Random random = new Random(8);
        int n = 3000;
        double[] xyz = new double[9 * n];
        for (int t = 0; t < n; t++) {
            Vec3 c = new Vec3(uniform(random, -5, 5), uniform(random, -5, 5), uniform(random, -5, 5));
            double size = uniform(random, 0.05, 1.5);
            for (int v = 0; v < 3; v++) {
                Vec3 p = c.plus(randomUnit(random).times(size));
                xyz[9 * t + 3 * v] = p.x();
                xyz[9 * t + 3 * v + 1] = p.y();
                xyz[9 * t + 3 * v + 2] = p.z();
            }
        }
        TriangleMesh mesh = new TriangleMesh(triangles(xyz));
        EachTriangle withoutBvh = new EachTriangle(mesh);
        Hit viaBvh = new Hit(), direct = new Hit();
        int found = 0;
        for (int i = 0; i < 10_000; i++) {
            // Half the rays start inside the soup's box, half outside aiming at it.
            Vec3 o = i % 2 == 0 ? new Vec3(uniform(random, -5, 5), uniform(random, -5, 5), uniform(random, -5, 5))
                    : randomUnit(random).times(20);
            Vec3 d = i % 2 == 0 ? randomUnit(random)
                    : new Vec3(uniform(random, -4, 4), uniform(random, -4, 4), uniform(random, -4, 4)).minus(o);
            Ray ray = new Ray(o, d);
            double tMax = random.nextInt(4) == 0 ? uniform(random, 0, 30) : Double.POSITIVE_INFINITY;

            boolean a = mesh.intersect(ray, tMax, viaBvh);
            boolean b = withoutBvh.intersect(ray, tMax, direct);

            assertEquals(b, a, ray.toString());
            assertEquals(b, mesh.occluded(ray, tMax), "any-hit for " + ray);
            if (a) {
                found++;
                assertEquals(direct.t, viaBvh.t, 0.0);
                assertVec(direct.point(), viaBvh.point(), 0.0);
                assertVec(direct.normal(), viaBvh.normal(), 0.0);
            }
        }
        assertTrue(found > 5000, "rays that hit: " + found);
    }

    @Test
    void geometricNormalFollowsTheWindingAndHitErrorBoundsAreSet() {
        TriangleMesh ccw = new TriangleMesh(triangles(0, 0, 0, 1, 0, 0, 0, 1, 0));
        TriangleMesh cw = new TriangleMesh(triangles(0, 0, 0, 0, 1, 0, 1, 0, 0));
        Hit hit = new Hit();

        assertTrue(ccw.intersect(new Ray(0.25, 0.25, 2, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertVec(new Vec3(0, 0, 1), hit.normal(), 0.0);
        assertEquals(2, hit.t, 0.0);
        assertVec(new Vec3(0.25, 0.25, 0), hit.point(), 1e-16);
        assertTrue(hit.ex > 0 && hit.ey > 0 && hit.ex < 1e-15);

        assertTrue(cw.intersect(new Ray(0.25, 0.25, 2, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertVec(new Vec3(0, 0, -1), hit.normal(), 0.0);
    }

    @Test
    void aUnitTriangleMovedScaledAndRotatedIsHitWhereTheTransformPutsIt() {
        Vec3 position = new Vec3(2, -3, 4), rotation = new Vec3(30, 45, 60);
        double scale = 2.5;
        TriangleMesh mesh = new TriangleMesh(triangles(0, 0, 0, 1, 0, 0, 0, 1, 0), position, scale, rotation);
        Rotation r = Rotation.fromEulerDegrees(rotation);
        Vec3 p0 = position, p1 = position.plus(r.apply(new Vec3(scale, 0, 0))), p2 = position.plus(r.apply(new Vec3(0, scale, 0)));
        Vec3 normal = r.apply(new Vec3(0, 0, 1));
        double[] world = mesh.positions();
        assertVec(p1, new Vec3(world[3], world[4], world[5]), 1e-15);
        assertVec(p2, new Vec3(world[6], world[7], world[8]), 1e-15);
        // Aim along -normal at a point inside the triangle, from 3 units in front of it.
        Vec3 target = p0.plus(p1.minus(p0).times(0.2)).plus(p2.minus(p0).times(0.3));
        Hit hit = new Hit();

        assertTrue(mesh.intersect(new Ray(target.plus(normal.times(3)), normal.negated()), Double.POSITIVE_INFINITY, hit));

        assertEquals(3, hit.t, 1e-14);
        assertVec(target, hit.point(), 1e-14);
        assertVec(normal, hit.normal(), 1e-15);
        // Just outside the first edge, the untransformed triangle's spot, and from behind with tMax short: misses.
        Vec3 outside = p0.plus(p1.minus(p0).times(0.5)).minus(p2.minus(p0).times(0.01));
        assertFalse(mesh.intersect(new Ray(outside.plus(normal.times(3)), normal.negated()), Double.POSITIVE_INFINITY, hit));
        assertFalse(mesh.intersect(new Ray(0.2, 0.3, 3, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertFalse(mesh.intersect(new Ray(target.plus(normal.times(3)), normal.negated()), 2.999, hit));
        assertEquals(new Vec3(2, -3, 4), mesh.position());
    }

    @Test
    void smoothNormalsInterpolateBarycentricallyAndTurnToTheGeometricSide() {
        double[] xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0};
        Vec3 n0 = new Vec3(0, 0, 1), n1 = new Vec3(1, 0, 1).normalized(), n2 = new Vec3(0, 1, 1).normalized();
        double[] normals = {n0.x(), n0.y(), n0.z(), n1.x(), n1.y(), n1.z(), n2.x(), n2.y(), n2.z()};
        TriangleMesh mesh = new TriangleMesh(new MeshData(xyz, new int[] {0, 1, 2}, normals));
        Hit hit = new Hit();
        double b1 = 0.2, b2 = 0.5, b0 = 1 - b1 - b2;

        assertTrue(mesh.intersect(new Ray(b1, b2, 1, 0, 0, -1), Double.POSITIVE_INFINITY, hit));

        Vec3 expected = n0.times(b0).plus(n1.times(b1)).plus(n2.times(b2)).normalized();
        assertVec(expected, hit.normal(), 1e-15);
        assertTrue(mesh.intersect(new Ray(1e-9, 1e-9, 1, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertVec(n0, hit.normal(), 1e-8);

        // Vertex normals pointing against the winding are turned to the geometric normal's side.
        double[] flipped = normals.clone();
        for (int i = 0; i < flipped.length; i++) {
            flipped[i] = -flipped[i];
        }
        TriangleMesh inverted = new TriangleMesh(new MeshData(xyz, new int[] {0, 1, 2}, flipped));
        assertTrue(inverted.intersect(new Ray(b1, b2, 1, 0, 0, -1), Double.POSITIVE_INFINITY, hit));
        assertVec(expected, hit.normal(), 1e-15);
    }

    @Test
    void zeroAreaTrianglesAreDroppedAndAMeshOfOnlyThoseIsRejected() {
        MeshData mixed = new MeshData(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0},
                new int[] {0, 1, 2, 0, 1, 3, 2, 2, 1, 0, 0, 0}, null);

        TriangleMesh mesh = new TriangleMesh(mixed);

        assertEquals(1, mesh.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.indices());
        MeshData degenerate = new MeshData(new double[] {0, 0, 0, 1, 1, 1, 2, 2, 2}, new int[] {0, 1, 2}, null);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new TriangleMesh(degenerate));
        assertTrue(e.getMessage().contains("no triangle with non-zero area"), e.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> new TriangleMesh(triangles(0, 0, 0, 1, 0, 0, 0, 1, 0), Vec3.ZERO, 0, Vec3.ZERO));
    }

    @Test
    void raysFromInsideAClosedMeshHitItsInsideAndLeaveThroughIt() {
        TriangleMesh sphere = new TriangleMesh(MeshShapes.icosphere(3), new Vec3(1, 2, 3), 2, Vec3.ZERO);
        Random random = new Random(10);
        Hit hit = new Hit();
        for (int i = 0; i < 1000; i++) {
            Vec3 o = new Vec3(1, 2, 3).plus(randomUnit(random).times(uniform(random, 0, 1.5)));
            Vec3 d = randomUnit(random);

            assertTrue(sphere.intersect(new Ray(o, d), Double.POSITIVE_INFINITY, hit));

            assertTrue(hit.normal().dot(d) > 0, "reported as leaving");
            assertEquals(2, hit.point().minus(new Vec3(1, 2, 3)).length(), 0.01);
        }
    }

    @Test
    void aRaySpawnedFromAFlatMeshHitNeverHitsTheMeshAgainOnTheWayOut() {
        MeshData smooth = MeshShapes.icosphere(4);
        TriangleMesh mesh = new TriangleMesh(new MeshData(smooth.positions(), smooth.indices(), null),
                new Vec3(1e3, -2e3, 5e2), 40, new Vec3(10, 20, 30));
        Random random = new Random(11);
        Hit hit = new Hit();
        int checked = 0;
        for (int i = 0; i < 10_000; i++) {
            Vec3 o = new Vec3(1e3, -2e3, 5e2).plus(randomUnit(random).times(200));
            Vec3 d = new Vec3(1e3, -2e3, 5e2).plus(randomUnit(random).times(30)).minus(o);
            if (!mesh.intersect(new Ray(o, d), Double.POSITIVE_INFINITY, hit)) {
                continue;
            }
            checked++;
            // Leaving on the outside of a convex mesh: nothing more to hit.
            Vec3 away = randomUnit(random);
            if (away.dot(hit.normal()) < 0) {
                away = away.negated();
            }
            Ray out = Rays.spawn(hit, away.x(), away.y(), away.z());
            assertFalse(mesh.occluded(out, Double.POSITIVE_INFINITY), "spawned " + out);
        }
        assertTrue(checked > 9000);
    }

    @Test
    void boundsAndCountsDescribeTheWorldSpaceMesh() {
        TriangleMesh mesh = new TriangleMesh(MeshShapes.icosphere(2), new Vec3(5, 0, 0), 3, Vec3.ZERO);

        assertEquals(320, mesh.triangleCount());
        assertEquals(2, mesh.bounds().minX(), 1e-12);
        assertEquals(8, mesh.bounds().maxX(), 1e-12);
        assertEquals(-3, mesh.bounds().minY(), 1e-12);
        assertEquals(mesh.vertexCount() * 3, mesh.positions().length);
        assertEquals(mesh.vertexCount() * 3, mesh.normals().length);
    }

    @Test
    void makingAMeshAsksTheGateForWhatItAllocates() {
        MeshData knot = MeshShapes.torusKnot(2, 3, 500, 200); // 200,000 triangles
        MeshData flat = new MeshData(knot.positions(), knot.indices(), null);
        CountingGate gate = new CountingGate();

        long allocated = CountingGate.allocatedBy(
                () -> new TriangleMesh(flat, new Vec3(1, 2, 3), 2, new Vec3(10, 20, 30), gate));

        assertTrue(allocated <= gate.granted() + CountingGate.SLACK, allocated + " allocated, " + gate.granted()
                + " granted");
        assertTrue(gate.granted() < 1.2 * allocated, "granted " + gate.granted() + " for " + allocated);
        CountingGate stingy = new CountingGate(gate.granted() / 2);
        assertTrue(CountingGate.allocatedBy(() -> new TriangleMesh(flat, Vec3.ZERO, 1, Vec3.ZERO, stingy))
                <= gate.granted() / 2 + CountingGate.SLACK, "a refusal stops the build");
    }

    @Test
    void aMovedMeshIsTheMeshBuiltWhereItWasMovedToWithoutBuildingItsTreeAgain() {
        MeshData knot = MeshShapes.torusKnot(2, 3, 120, 24);
        Vec3 rotation = new Vec3(10, 20, 30), there = new Vec3(-3.25, 0.7, 1e3);
        TriangleMesh here = new TriangleMesh(knot, new Vec3(1, 2, 3), 0.75, rotation);

        TriangleMesh moved = here.movedTo(there, MemoryGate.UNLIMITED);
        TriangleMesh built = new TriangleMesh(knot, there, 0.75, rotation);

        assertEquals(0, moved.buildNanos(), "no tree built");
        assertTrue(built.buildNanos() > 0);
        assertEquals(there, moved.position());
        assertArrayEquals(built.positions(), moved.positions());
        assertArrayEquals(built.indices(), moved.indices());
        assertArrayEquals(built.normals(), moved.normals());
        assertEquals(built.bounds(), moved.bounds());
        assertSameHits(built, moved, there, 20_000);
    }

    @Test
    void aMoveThatFlattensATriangleBuildsTheMeshAfresh() {
        // a tiny triangle beside a large one: far from the origin its corners round onto one point
        MeshData mesh = new MeshData(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 5 + 1e-9, 5, 5, 5, 5 + 1e-9, 5},
                new int[] {0, 1, 2, 3, 4, 5}, null);
        TriangleMesh near = new TriangleMesh(mesh, Vec3.ZERO, 1, Vec3.ZERO);
        Vec3 far = new Vec3(1e9, 1e9, 0);

        TriangleMesh moved = near.movedTo(far, MemoryGate.UNLIMITED);
        TriangleMesh built = new TriangleMesh(mesh, far, 1, Vec3.ZERO);

        assertEquals(2, near.triangleCount());
        assertEquals(1, built.triangleCount(), "the flattened triangle is dropped");
        assertEquals(1, moved.triangleCount());
        assertArrayEquals(built.indices(), moved.indices());
        assertArrayEquals(built.positions(), moved.positions());
        assertSameHits(built, moved, new Vec3(1e9 + 0.3, 1e9 + 0.3, 0), 4_000);
    }

    /** The same hit, to the bit, for rays from around {@code centre} towards the meshes. */
    private static void assertSameHits(TriangleMesh expected, TriangleMesh actual, Vec3 centre, int rays) {
        Random random = new Random(5);
        Hit a = new Hit(), b = new Hit();
        int hits = 0;
        for (int i = 0; i < rays; i++) {
            Vec3 from = centre.plus(new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()).times(4));
            Vec3 to = centre.plus(new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian()));
            Ray ray = new Ray(from, to.minus(from));
            boolean hit = expected.intersect(ray, Double.POSITIVE_INFINITY, a);
            assertEquals(hit, actual.intersect(ray, Double.POSITIVE_INFINITY, b));
            assertEquals(hit, actual.occluded(ray, Double.POSITIVE_INFINITY));
            if (hit) {
                hits++;
                assertEquals(a.t, b.t, 0.0);
                assertEquals(a.px, b.px, 0.0);
                assertEquals(a.nx, b.nx, 0.0);
                assertEquals(a.gz, b.gz, 0.0);
            }
        }
        assertTrue(hits > rays / 50, "rays that hit: " + hits);
    }
}
