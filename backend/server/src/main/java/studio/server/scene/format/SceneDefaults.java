package studio.server.scene.format;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Srgb;

/**
 * Defaults of the scene format, for every field a file leaves out (material coefficients come
 * from the engine's MaterialDefaults). The one place they live: the mapper fills them in, and the
 * published JSON Schema states them ({@code "default"}, from {@link #of}), which the editor's
 * defaults are tested against. Change them deliberately.
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
     * pixels stop at 1 sample, edges take up to render.samples. With the other samplers it defaults to 0.
     */
    public static final double ADAPTIVE = 0.05;
    /** Used when a scene has no "lights" field at all; an empty list means no lights. */
    public static final List<Double> LIGHT_POSITION = List.of(5.0, 8.0, 5.0);
    public static final String LIGHT_COLOR = "#ffffff";
    public static final double LIGHT_INTENSITY = 1.0;
    /** A point light's radius: 0, a point. */
    public static final double LIGHT_RADIUS = 0;
    /** Where an area light faces, and its size in metres. */
    public static final List<Double> AREA_LIGHT_LOOK_AT = List.of(0.0, 0.0, 0.0);
    public static final List<Double> AREA_LIGHT_SIZE = List.of(1.0, 1.0);
    public static final List<Double> ORIGIN = List.of(0.0, 0.0, 0.0);
    public static final List<Double> SPHERE_CENTER = List.of(0.0, 1.0, 0.0);
    public static final double SPHERE_RADIUS = 1;
    public static final List<Double> BOX_CENTER = List.of(0.0, 0.5, 0.0);
    public static final List<Double> BOX_SIZE = List.of(1.0, 1.0, 1.0);
    public static final List<Double> PLANE_NORMAL = List.of(0.0, 1.0, 0.0);
    public static final String MATERIAL = "chalk";

    private SceneDefaults() {
    }

    /** The default of each field with one, by record. render.adaptive has none alone: it depends on the sampler. */
    private static final Map<Class<?>, Map<String, Object>> FIELDS = Map.ofEntries(
            Map.entry(SceneDto.class, Map.of("version", SceneDto.FORMAT_VERSION, "name", NAME, "background", BACKGROUND,
                    "ambient", AMBIENT)),
            Map.entry(ImageDto.class, Map.of("width", WIDTH, "height", HEIGHT, "format", FORMAT, "quality", JPEG_QUALITY)),
            Map.entry(CameraDto.class, Map.of("position", CAMERA_POSITION, "lookAt", CAMERA_LOOK_AT, "up", CAMERA_UP,
                    "fov", CAMERA_FOV_DEGREES)),
            Map.entry(RenderDto.class, Map.of("sampler", SAMPLER, "samples", SAMPLES, "maxDepth", MAX_DEPTH, "seed", SEED)),
            Map.entry(LightDto.Point.class, Map.of("position", LIGHT_POSITION, "color", LIGHT_COLOR, "intensity", LIGHT_INTENSITY,
                    "falloff", false, "radius", LIGHT_RADIUS)),
            Map.entry(LightDto.Area.class, Map.of("position", LIGHT_POSITION, "size", AREA_LIGHT_SIZE, "lookAt", AREA_LIGHT_LOOK_AT,
                    "color", LIGHT_COLOR, "intensity", LIGHT_INTENSITY, "falloff", false, "twoSided", false)),
            Map.entry(ObjectDto.Sphere.class, Map.of("center", SPHERE_CENTER, "radius", SPHERE_RADIUS)),
            Map.entry(ObjectDto.Box.class, Map.of("center", BOX_CENTER, "size", BOX_SIZE, "rotation", ORIGIN)),
            Map.entry(ObjectDto.Plane.class, Map.of("point", ORIGIN, "normal", PLANE_NORMAL)),
            Map.entry(ObjectDto.Mesh.class, Map.of("position", ORIGIN, "scale", MESH_SCALE, "rotation", ORIGIN)),
            Map.entry(ObjectDto.Gltf.class, Map.of("position", ORIGIN, "scale", MESH_SCALE, "rotation", ORIGIN)));

    /**
     * The default of a field of one of the format's records, as the schema publishes it, or null
     * when it has none (a required field, a list, or one whose default depends on another field).
     * A material's come from the engine's {@link MaterialDefaults} for its kind, its colour as
     * {@code #rrggbb}.
     */
    public static Object of(Class<?> record, String field) {
        if (MaterialDto.class.isAssignableFrom(record) && record != MaterialDto.class) {
            return materialDefaults(MaterialKind.valueOf(record.getSimpleName().toUpperCase(Locale.ROOT))).get(field);
        }
        return FIELDS.getOrDefault(record, Map.of()).get(field);
    }

    private static Map<String, Object> materialDefaults(MaterialKind kind) {
        Material m = MaterialDefaults.of(kind, null);
        Map<String, Object> fields = new LinkedHashMap<>();
        fields.put("color", hex(m.color()));
        fields.put("diffuse", m.diffuse());
        fields.put("specular", m.specular());
        fields.put("shininess", m.shininess());
        fields.put("reflectivity", m.reflectivity());
        fields.put("ior", m.ior());
        return fields;
    }

    private static String hex(Rgb linear) {
        return String.format(Locale.ROOT, "#%02x%02x%02x", byte8(linear.r()), byte8(linear.g()), byte8(linear.b()));
    }

    private static int byte8(double linear) {
        return (int) Math.round(Srgb.fromLinear(linear) * 255);
    }
}
