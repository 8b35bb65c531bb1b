package studio.engine.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static studio.engine.geometry.GeometryAssertions.randomUnit;
import static studio.engine.geometry.GeometryAssertions.uniform;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;

import studio.engine.math.Vec3;
import studio.engine.memory.CountingGate;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.MeshShapes;

/**
 * Light buffers answer every shadow ray exactly as the mesh's tree does (NUM-13), decide nearly all
 * rays aimed at their light themselves, and are made only where they can be.
 */
class LightBufferTest {

    private static final double SHADOW_END = 1 - 1e-9; // as the integrator's shadow rays

    private static TriangleMesh knot() {
        return new TriangleMesh(MeshShapes.torusKnot(2, 3, 300, 16), new Vec3(0.3, 1.6, -0.2), 0.8,
                new Vec3(-20, 25, 15));
    }

    /** Lights on every side of the knot, near its box and far from it. */
    private static final List<Vec3> LIGHTS = List.of(new Vec3(-3, 6, 4), new Vec3(5, 4, -2), new Vec3(0.2, -4, 0.1),
            new Vec3(0.3, 1.6, 3.2));

    @Test
    @DisplayName("NUM-13: shadow rays from the mesh, a floor under it and the space around it: the buffers' answers are the tree's")
    void shadowRaysTowardsTheLightAreAnsweredAsTheTreeAnswersThem() {
        TriangleMesh plain = knot();
        TriangleMesh lit = plain.withLightBuffers(LIGHTS, MemoryGate.UNLIMITED);
        assertBuffersFor(plain, LIGHTS, 4);
        Random random = new Random(13);
        Hit hit = new Hit();
        int[] decided = new int[2];
        int rays = 0, blocked = 0;
        for (Vec3 light : LIGHTS) {
            LightBuffer buffer = buffer(lit, light);
            for (int i = 0; i < 20_000; i++) {
                Vec3 from;
                Hit surface = null;
                switch (i % 3) {
                    case 0 -> { // a point on the knot, as a camera ray finds it
                        Vec3 eye = new Vec3(0.3, 1.6, -0.2).plus(randomUnit(random).times(6));
                        Vec3 at = new Vec3(0.3, 1.6, -0.2).plus(randomUnit(random).times(0.6));
                        Vec3 d = at.minus(eye).normalized();
                        if (!plain.intersect(new Ray(eye.x(), eye.y(), eye.z(), d.x(), d.y(), d.z()), Double.POSITIVE_INFINITY, hit)) {
                            continue;
                        }
                        surface = hit;
                        from = null;
                    }
                    case 1 -> from = new Vec3(uniform(random, -4, 4), uniform(random, -1, 0.5), uniform(random, -4, 4));
                    default -> from = new Vec3(uniform(random, -1.5, 2), uniform(random, 0, 3.2), uniform(random, -2, 1.6));
                }
                Ray ray = surface != null ? Rays.spawnTowards(surface, light.x(), light.y(), light.z()) : towards(from, light);
                double ex = light.x() - ray.ox, ey = light.y() - ray.oy, ez = light.z() - ray.oz;
                double tMax = Math.sqrt(ex * ex + ey * ey + ez * ez) * SHADOW_END;
                boolean expected = plain.occluded(ray, tMax);
                assertEquals(expected, lit.occluded(ray, tMax), () -> ray + " towards " + light);
                int answer = occludedByBuffer(buffer, ray, tMax);
                if (answer >= 0) {
                    assertEquals(expected ? 1 : 0, answer, () -> ray + " towards " + light);
                    decided[0]++;
                }
                decided[1]++;
                rays++;
                blocked += expected ? 1 : 0;
            }
        }
        assertTrue(decided[0] > 0.99 * decided[1], decided[0] + " of " + decided[1] + " rays decided by the buffer");
        assertTrue(blocked > rays / 10 && blocked < rays * 9 / 10, blocked + " of " + rays + " blocked");
    }

    @Test
    void raysAimedAnywhereAreAnsweredAsTheTreeAnswersThem() {
        TriangleMesh plain = knot();
        TriangleMesh lit = plain.withLightBuffers(LIGHTS, MemoryGate.UNLIMITED);
        Random random = new Random(14);
        LightBuffer[] buffers = LIGHTS.stream().map(light -> buffer(lit, light)).toArray(LightBuffer[]::new);
        int decided = 0;
        for (int i = 0; i < 40_000; i++) {
            Vec3 o = new Vec3(uniform(random, -3, 3.6), uniform(random, -1, 4.2), uniform(random, -3.2, 2.8));
            Vec3 d = randomUnit(random);
            double tMax = i % 4 == 0 ? Double.POSITIVE_INFINITY : uniform(random, 0, 5);
            Ray ray = new Ray(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            assertEquals(plain.occluded(ray, tMax), lit.occluded(ray, tMax), ray::toString);
            for (int k = 0; k < buffers.length; k++) {
                int answer = occludedByBuffer(buffers[k], ray, tMax);
                Vec3 light = LIGHTS.get(k);
                if (answer >= 0) {
                    assertEquals(plain.occluded(ray, tMax) ? 1 : 0, answer, () -> ray + " in the buffer of " + light);
                    decided++;
                }
            }
        }
        assertTrue(decided > 1000, decided + " rays decided by some buffer (those missing the box, short ones)");
    }

    @Test
    @DisplayName("NUM-13: rays to the light through a grid's shared vertices and edges, and along cell borders, are all blocked")
    void raysThroughSharedVerticesAndEdgesAreBlocked() {
        // a 40 x 40 grid of quads (3,200 triangles) in the plane y = 1, the light above it
        int n = 40;
        double[] positions = new double[3 * (n + 1) * (n + 1)];
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                int v = 3 * (j * (n + 1) + i);
                positions[v] = -1 + 2.0 * i / n;
                positions[v + 1] = 1;
                positions[v + 2] = -1 + 2.0 * j / n;
            }
        }
        int[] indices = new int[6 * n * n];
        for (int j = 0, k = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
                indices[k++] = a; indices[k++] = c; indices[k++] = b;
                indices[k++] = b; indices[k++] = c; indices[k++] = d;
            }
        }
        TriangleMesh plain = new TriangleMesh(new MeshData(positions, indices, null));
        Vec3 light = new Vec3(0.013, 4, -0.021);
        TriangleMesh lit = plain.withLightBuffers(List.of(light), MemoryGate.UNLIMITED);
        assertBuffersFor(plain, List.of(light), 1);
        LightBuffer buffer = buffer(lit, light);
        int rays = 0;
        for (int j = 0; j <= 4 * n; j++) {
            for (int i = 0; i <= 4 * n; i++) {
                // through every vertex, and three points along each edge, of the inner grid
                double x = -0.95 + 1.9 * i / (4 * n), z = -0.95 + 1.9 * j / (4 * n);
                double s = 2.5; // from below the grid, as far below it as the light is above
                Vec3 from = new Vec3(light.x() + s * (x - light.x()), light.y() + s * (1 - light.y()), light.z() + s * (z - light.z()));
                Ray ray = towards(from, light);
                double tMax = from.minus(light).length() * SHADOW_END;
                assertTrue(plain.occluded(ray, tMax), ray::toString);
                assertTrue(lit.occluded(ray, tMax), ray::toString);
                assertEquals(1, occludedByBuffer(buffer, ray, tMax), ray::toString);
                rays++;
            }
        }
        assertEquals((4 * n + 1) * (4 * n + 1), rays);
    }

    @Test
    @DisplayName("NUM-13: a large triangle lies nearer the light than its vertices: points just under it stay in its shadow")
    void aLargeTriangleNearerTheLightThanItsVerticesStillShadowsThePointsUnderIt() {
        // a 20 x 20 square of two triangles, the light 1 above its centre; points 0.01 under it
        MeshData square = new MeshData(new double[] {-10, 0, -10, 10, 0, -10, 10, 0, 10, -10, 0, 10},
                new int[] {0, 2, 1, 0, 3, 2}, null);
        TriangleMesh plain = new TriangleMesh(square);
        Vec3 light = new Vec3(0.1, 1, -0.2);
        TriangleMesh lit = plain.withLightBuffers(List.of(light), MemoryGate.UNLIMITED);
        assertBuffersFor(plain, List.of(light), 1);
        LightBuffer buffer = buffer(lit, light);
        int shadowed = 0, points = 0;
        for (int j = -20; j <= 20; j++) {
            for (int i = -20; i <= 20; i++) {
                Vec3 from = new Vec3(0.25 * i, -0.01, 0.25 * j);
                Ray ray = towards(from, light);
                double tMax = from.minus(light).length() * SHADOW_END;
                assertTrue(plain.occluded(ray, tMax));
                shadowed += lit.occluded(ray, tMax) && occludedByBuffer(buffer, ray, tMax) == 1 ? 1 : 0;
                points++;
            }
        }
        assertEquals(points, shadowed, "points under the square in its shadow");
    }

    @Test
    void aLightInsideTheBoxTooCloseToItOrTooFarToTheSideHasNoBuffer() {
        TriangleMesh mesh = knot();
        assertNull(buffer(mesh, new Vec3(0.3, 1.6, -0.2)), "inside the box");
        var box = mesh.bounds();
        assertNull(buffer(mesh, new Vec3(box.minX() - 1e-4, 1.6, -0.2)), "a ten-thousandth from its face");
        assertNotNull(buffer(mesh, new Vec3(box.minX() - 0.1, 1.6, -0.2)), "a tenth from its face");
        assertNull(buffer(mesh, new Vec3(box.maxX() + 0.01, box.maxY() + 0.01, box.maxZ() + 0.01)),
                "just off a corner, seeing the box across nearly a half-space");
        assertBuffersFor(mesh, List.of(new Vec3(0.3, 1.6, -0.2), new Vec3(-3, 6, 4)), 1);
    }

    /**
     * A mesh keeps its buffers for the same lights; a moved copy keeps none of the old place's, and
     * answers shadow rays as a mesh made at its new place; of five lights the first
     * {@link LightBuffer#MAX_LIGHTS} get buffers.
     */
    @Test
    void aMeshKeepsItsBuffersForTheSameLightsAndAMovedOneAnswersForItsNewPlace() {
        TriangleMesh lit = knot().withLightBuffers(LIGHTS, MemoryGate.UNLIMITED);
        assertSame(lit, lit.withLightBuffers(List.copyOf(LIGHTS), MemoryGate.UNLIMITED));
        Vec3 place = new Vec3(0.8, 1.9, 0.1);
        TriangleMesh moved = lit.movedTo(place, MemoryGate.UNLIMITED);
        TriangleMesh fresh = new TriangleMesh(MeshShapes.torusKnot(2, 3, 300, 16), place, 0.8, new Vec3(-20, 25, 15));
        Random random = new Random(15);
        int blocked = 0, changed = 0;
        for (int i = 0; i < 20_000; i++) {
            Vec3 light = LIGHTS.get(i % LIGHTS.size());
            Vec3 from = new Vec3(uniform(random, -1.5, 2.5), uniform(random, 0, 3.5), uniform(random, -2, 2));
            Ray ray = towards(from, light);
            double tMax = from.minus(light).length() * SHADOW_END;
            boolean expected = fresh.occluded(ray, tMax);
            assertEquals(expected, moved.occluded(ray, tMax), () -> ray + " towards " + light);
            blocked += expected ? 1 : 0;
            changed += expected != lit.occluded(ray, tMax) ? 1 : 0;
        }
        assertTrue(blocked > 1000 && changed > 1000, blocked + " blocked, " + changed + " changed by the move");
        assertBuffersFor(knot(),
                List.of(new Vec3(-3, 6, 4), new Vec3(5, 4, -2), new Vec3(0, 9, 0), new Vec3(9, 0, 0), new Vec3(0, 0, 9)),
                LightBuffer.MAX_LIGHTS);
    }

    /**
     * Giving {@code mesh} buffers for these lights asks the gate for just what building one buffer
     * for each of the first {@link LightBuffer#MAX_LIGHTS} of them asks, and {@code count} of those
     * lights can have one (a light that cannot asks nothing).
     */
    private static void assertBuffersFor(TriangleMesh mesh, List<Vec3> lights, int count) {
        CountingGate gate = new CountingGate();
        mesh.withLightBuffers(lights, gate);
        long each = 0;
        int made = 0;
        for (Vec3 light : lights.subList(0, Math.min(lights.size(), LightBuffer.MAX_LIGHTS))) {
            CountingGate own = new CountingGate();
            LightBuffer buffer = buffer(mesh, light, own);
            made += buffer != null ? 1 : 0;
            assertEquals(buffer != null, own.granted() > 0, () -> "memory asked for the buffer of " + light);
            each += own.granted();
        }
        assertEquals(count, made, "lights that can have a buffer");
        assertEquals(each, gate.granted(), "the mesh's buffers ask what those lights' buffers ask");
    }

    @Test
    void theListsStayShortAndMakingThemAsksTheGateFirst() {
        TriangleMesh mesh = new TriangleMesh(MeshShapes.torusKnot(2, 3, 500, 100), Vec3.ZERO, 1, Vec3.ZERO);
        CountingGate gate = new CountingGate();
        LightBuffer[] made = new LightBuffer[1];
        double[] positions = mesh.positions();
        int[] indices = mesh.indices();
        Vec3 light = new Vec3(-3, 6, 4);
        long allocated = CountingGate.allocatedBy(
                () -> made[0] = LightBuffer.ofTriangles(positions, indices, mesh.bounds(), light, mesh::occludedBy, gate));
        assertNotNull(made[0], "a buffer for a light clear of the knot's box");
        assertTrue(allocated <= gate.granted() + CountingGate.SLACK, allocated + " allocated, " + gate.granted() + " granted");
        // about 64 bytes a triangle and 14 an entry of the lists (two ints, a float, their share of
        // the cells): under 140 bytes a triangle is under 6 entries a triangle
        assertTrue(allocated < 140L * mesh.triangleCount(), allocated / mesh.triangleCount() + " bytes a triangle");
        // cells about as small as a triangle's shadow: a ray aimed at the light tests a few triangles
        double tested = trianglesTestedPerShadowRay(mesh, light, positions, indices);
        // each entry keeps its triangle's rectangle within the cell: of a cell's list (8.5 triangles
        // tested a ray without it) a ray aimed at the light tests those whose shadow holds its point
        assertTrue(tested < 4, tested + " triangles tested a shadow ray");
        CountingGate stingy = new CountingGate(gate.granted() / 2);
        assertNull(LightBuffer.ofTriangles(positions, indices, mesh.bounds(), light, mesh::occludedBy, stingy),
                "memory not free: no buffer, and no refusal");
        assertTrue(stingy.granted() <= gate.granted() / 2);
    }

    /**
     * Triangles the buffer of {@code light} tests, on average, for a shadow ray from a point of the
     * mesh a camera ray finds towards the light.
     */
    private static double trianglesTestedPerShadowRay(TriangleMesh mesh, Vec3 light, double[] positions, int[] indices) {
        long[] tests = new long[1];
        LightBuffer buffer = LightBuffer.ofTriangles(positions, indices, mesh.bounds(), light,
                (tri, ray, tMax) -> {
                    tests[0]++;
                    return mesh.occludedBy(tri, ray, tMax);
                }, MemoryGate.UNLIMITED);
        Random random = new Random(16);
        Hit hit = new Hit();
        var box = mesh.bounds();
        Vec3 centre = new Vec3((box.minX() + box.maxX()) / 2, (box.minY() + box.maxY()) / 2, (box.minZ() + box.maxZ()) / 2);
        int rays = 0;
        while (rays < 2_000) {
            Vec3 eye = centre.plus(randomUnit(random).times(6));
            Vec3 d = centre.plus(randomUnit(random).times(0.6)).minus(eye).normalized();
            if (mesh.intersect(new Ray(eye.x(), eye.y(), eye.z(), d.x(), d.y(), d.z()), Double.POSITIVE_INFINITY, hit)) {
                Ray ray = Rays.spawnTowards(hit, light.x(), light.y(), light.z());
                double ex = light.x() - ray.ox, ey = light.y() - ray.oy, ez = light.z() - ray.oz;
                buffer.occluder(ray, Math.sqrt(ex * ex + ey * ey + ez * ez) * SHADOW_END);
                rays++;
            }
        }
        return (double) tests[0] / rays;
    }

    private static LightBuffer buffer(TriangleMesh mesh, Vec3 light) {
        return buffer(mesh, light, MemoryGate.UNLIMITED);
    }

    private static LightBuffer buffer(TriangleMesh mesh, Vec3 light, MemoryGate memory) {
        return LightBuffer.ofTriangles(mesh.positions(), mesh.indices(), mesh.bounds(), light, mesh::occludedBy, memory);
    }

    /** A shadow ray as the integrator makes one: unit direction from {@code from} to the light. */
    private static Ray towards(Vec3 from, Vec3 light) {
        Vec3 d = light.minus(from).normalized();
        return new Ray(from.x(), from.y(), from.z(), d.x(), d.y(), d.z());
    }

    /** The buffer's answer: 1 blocked, 0 not, -1 left to the tree. */
    private static int occludedByBuffer(LightBuffer buffer, Ray ray, double tMax) {
        int occluder = buffer.occluder(ray, tMax);
        return occluder == LightBuffer.UNDECIDED ? -1 : occluder >= 0 ? 1 : 0;
    }
}
