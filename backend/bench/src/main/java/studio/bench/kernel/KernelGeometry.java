package studio.bench.kernel;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;
import studio.engine.scene.Scene;

/**
 * A compiled scene's geometry, camera and first light, written as the text file that
 * {@code backend/bench/embree/embree_rays} reads, so Embree traces the very shapes our engine
 * does: world space, after the server's SceneCompiler has applied every default and placed every
 * mesh. One record a line, numbers as {@link Double#toString} writes them (they read back exactly):
 * <pre>
 * image W H
 * camera px py pz  ux uy uz  vx vy vz  wx wy wz  tanHalfFov     (position, right, up, backward)
 * light x y z
 * sphere cx cy cz r
 * plane px py pz nx ny nz
 * triangles V T                  then V lines "x y z" and T lines "a b c" (counter-clockwise from outside)
 * </pre>
 * A box is written as its 12 triangles; a mesh as its placed vertices and indices.
 */
final class KernelGeometry {

    /** A box's faces as quads of corner indices (bit 0: +x, bit 1: +y, bit 2: +z), counter-clockwise from outside. */
    private static final int[][] BOX_FACES = {
            {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

    private KernelGeometry() {
    }

    /**
     * Writes {@code scene} to {@code file} for an image of {@code width} x {@code height};
     * {@code fovDegrees} is the camera's vertical field of view, which the engine's Camera keeps to itself.
     *
     * @throws IllegalArgumentException if the scene has no light
     */
    static void write(Scene scene, double fovDegrees, int width, int height, Path file) throws IOException {
        if (scene.lights().isEmpty()) {
            throw new IllegalArgumentException("the scene has no light to send shadow rays to");
        }
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            out.write("# studio-bench kernel geometry: " + scene.objectCount() + " objects\n");
            out.write("image " + width + " " + height + "\n");
            Camera c = scene.camera();
            out.write("camera " + xyz(c.position()) + " " + xyz(c.right()) + " " + xyz(c.upward()) + " "
                    + xyz(c.backward()) + " " + Math.tan(Math.toRadians(fovDegrees) / 2) + "\n");
            out.write("light " + xyz(scene.lights().get(0).position()) + "\n");
            for (int i = 0; i < scene.objectCount(); i++) {
                Shape shape = scene.shape(i);
                if (shape instanceof Sphere s) {
                    out.write("sphere " + xyz(s.center()) + " " + s.radius() + "\n");
                } else if (shape instanceof Plane p) {
                    out.write("plane " + xyz(p.point()) + " " + xyz(p.normal()) + "\n");
                } else if (shape instanceof Box b) {
                    writeBox(b, out);
                } else {
                    TriangleMesh m = (TriangleMesh) shape;
                    writeTriangles(m.positions(), m.indices(), out);
                }
            }
        }
    }

    /** The box's 8 corners, placed as {@link Box} places them (centre plus rotation times half size), and 12 triangles. */
    private static void writeBox(Box box, Writer out) throws IOException {
        Rotation r = Rotation.fromEulerDegrees(box.rotationDegrees());
        Vec3 c = box.center(), half = box.size().times(0.5);
        double[] corners = new double[24];
        for (int k = 0; k < 8; k++) {
            Vec3 p = c.plus(r.apply(new Vec3((k & 1) != 0 ? half.x() : -half.x(), (k & 2) != 0 ? half.y() : -half.y(),
                    (k & 4) != 0 ? half.z() : -half.z())));
            corners[3 * k] = p.x();
            corners[3 * k + 1] = p.y();
            corners[3 * k + 2] = p.z();
        }
        int[] indices = new int[36];
        int n = 0;
        for (int[] q : BOX_FACES) {
            int[] two = {q[0], q[1], q[2], q[0], q[2], q[3]};
            System.arraycopy(two, 0, indices, n, 6);
            n += 6;
        }
        writeTriangles(corners, indices, out);
    }

    private static void writeTriangles(double[] positions, int[] indices, Writer out) throws IOException {
        out.write("triangles " + positions.length / 3 + " " + indices.length / 3 + "\n");
        StringBuilder line = new StringBuilder(80);
        for (int i = 0; i < positions.length; i += 3) {
            line.setLength(0);
            line.append(positions[i]).append(' ').append(positions[i + 1]).append(' ').append(positions[i + 2]).append('\n');
            out.append(line);
        }
        for (int i = 0; i < indices.length; i += 3) {
            line.setLength(0);
            line.append(indices[i]).append(' ').append(indices[i + 1]).append(' ').append(indices[i + 2]).append('\n');
            out.append(line);
        }
    }

    private static String xyz(Vec3 v) {
        return v.x() + " " + v.y() + " " + v.z();
    }
}
