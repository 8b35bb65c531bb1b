package studio.server.scene.format;

import java.util.List;

/**
 * Defaults of the scene format, for every field a file leaves out (material coefficients come
 * from the engine's MaterialDefaults). Published with the format, so change them deliberately.
 */
public final class SceneDefaults {

    public static final String NAME = "render";
    public static final int WIDTH = 800;
    public static final int HEIGHT = 600;
    public static final String FORMAT = "png";
    public static final double JPEG_QUALITY = 0.92;
    public static final List<Double> CAMERA_POSITION = List.of(0.0, 2.0, 8.0);
    public static final List<Double> CAMERA_LOOK_AT = List.of(0.0, 0.0, 0.0);
    public static final List<Double> CAMERA_UP = List.of(0.0, 1.0, 0.0);
    public static final double CAMERA_FOV_DEGREES = 50;
    public static final String BACKGROUND = "#20232a";
    public static final double AMBIENT = 0.08;
    public static final double MESH_SCALE = 1.0;
    public static final String SAMPLER = "sobol";
    public static final int SAMPLES = 16;
    public static final int MAX_DEPTH = 6;
    public static final long SEED = 0;
    /**
     * The adaptive-sampling threshold with the sobol sampler (0: off, every pixel takes render.samples
     * samples): sobol with adaptive sampling wins the speed-against-accuracy chart (docs/bench); flat
     * pixels stop at 4 samples, edges take up to render.samples. With the other samplers it defaults to 0.
     */
    public static final double ADAPTIVE = 0.05;
    /** Used when a scene has no "lights" field at all; an empty list means no lights. */
    public static final List<Double> LIGHT_POSITION = List.of(5.0, 8.0, 5.0);
    public static final String LIGHT_COLOR = "#ffffff";
    public static final double LIGHT_INTENSITY = 1.0;
    public static final List<Double> ORIGIN = List.of(0.0, 0.0, 0.0);
    public static final List<Double> SPHERE_CENTER = List.of(0.0, 1.0, 0.0);
    public static final double SPHERE_RADIUS = 1;
    public static final List<Double> BOX_CENTER = List.of(0.0, 0.5, 0.0);
    public static final List<Double> BOX_SIZE = List.of(1.0, 1.0, 1.0);
    public static final List<Double> PLANE_NORMAL = List.of(0.0, 1.0, 0.0);
    public static final String MATERIAL = "chalk";

    private SceneDefaults() {
    }
}
