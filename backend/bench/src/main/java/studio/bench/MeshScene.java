package studio.bench;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import studio.engine.mesh.MeshData;
import studio.engine.mesh.MeshShapes;
import studio.engine.mesh.ObjWriter;

/**
 * The "mesh-100k" benchmark scene: a (2, 3) torus knot of {@value #SEGMENTS} x {@value #SIDES} x 2 =
 * 104,000 smooth-shaded triangles (the engine's {@link MeshShapes#torusKnot}), turned about all three
 * axes (the trefoil about facing the camera) above a ground plane, lit as the still life. The mesh
 * is an OBJ file beside the scene file, which names it in {@code "file"}, as a scene with a large
 * mesh is written.
 */
public final class MeshScene {

    /** The OBJ file's name, in the scene file's folder. */
    public static final String OBJ_FILE = "torus-knot-100k.obj";
    static final int SEGMENTS = 1000, SIDES = 52;
    /** Decimals of the OBJ numbers, as modelling tools write them: a file half the size, parsed as fast by every reader. */
    static final int OBJ_DECIMALS = 6;

    private MeshScene() {
    }

    /** The knot in object space: 104,000 triangles, 52,000 vertices with normals. */
    public static MeshData mesh() {
        return MeshShapes.torusKnot(2, 3, SEGMENTS, SIDES);
    }

    /** Writes {@code mesh} as OBJ text to {@code file}. */
    public static void writeObj(MeshData mesh, Path file) throws IOException {
        try (Writer out = Files.newBufferedWriter(file, StandardCharsets.UTF_8)) {
            out.write("# torus knot (2, 3), " + mesh.triangleCount() + " triangles, MeshShapes.torusKnot, by studio-bench\n");
            ObjWriter.write(mesh, out, OBJ_DECIMALS);
        }
    }

    /** The scene file, its mesh read from {@code objFile} (relative to the scene file's folder). */
    public static String json(String objFile) {
        return """
                {
                  "version": 1,
                  "name": "mesh-100k",
                  "camera": { "position": [0, 3.2, 7.5], "lookAt": [0, 1.4, 0], "up": [0, 1, 0], "fov": 40 },
                  "background": "#2a2f38",
                  "ambient": 0.07,
                  "render": { "sampler": "jittered", "samples": 16, "maxDepth": 6 },
                  "lights": [
                    { "type": "point", "position": [-3, 6, 4], "color": "#ffffff", "intensity": 0.85 },
                    { "type": "point", "position": [5, 4, -2], "color": "#ffd8a8", "intensity": 0.35 }
                  ],
                  "objects": [
                    { "type": "mesh", "file": "%s", "position": [0, 1.6, 0], "scale": 0.8, "rotation": [-20, 25, 15],
                      "material": { "type": "plastic", "color": "#e0a030" } },
                    { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": { "type": "chalk", "color": "#c8c0b0" } }
                  ]
                }
                """.formatted(objFile);
    }
}
