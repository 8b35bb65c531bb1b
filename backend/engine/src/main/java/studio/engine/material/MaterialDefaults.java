package studio.engine.material;

import studio.engine.math.Rgb;

/** The one place material defaults live: every coefficient a scene leaves out comes from here. */
public final class MaterialDefaults {

    /** sRGB #cccccc, a light grey, in linear light. */
    public static final Rgb GREY = Rgb.fromSrgb8(0xcc, 0xcc, 0xcc);

    private MaterialDefaults() {
    }

    /** The colour a material of this kind has when the scene gives none. */
    public static Rgb color(MaterialKind kind) {
        return switch (kind) {
            case MIRROR, GLASS -> Rgb.WHITE;
            default -> GREY;
        };
    }

    /**
     * A material of the given kind; each {@code null} argument takes the kind's default.
     * Coefficients a kind does not use are zero.
     */
    public static Material of(MaterialKind kind, Rgb color, Double diffuse, Double specular, Double shininess,
                              Double reflectivity, Double ior) {
        Rgb c = color != null ? color : color(kind);
        return switch (kind) {
            case FLAT -> new Material(kind, c, 0, 0, 0, 0, 1);
            case CHALK -> new Material(kind, c, or(diffuse, 0.9), 0, 0, 0, 1);
            case PLASTIC -> new Material(kind, c, or(diffuse, 0.8), or(specular, 0.5), or(shininess, 60), 0, 1);
            case METAL -> new Material(kind, c, or(diffuse, 0.15), or(specular, 0.8), or(shininess, 120),
                    or(reflectivity, 0.5), 1);
            case MIRROR -> new Material(kind, c, 0, 0, 0, or(reflectivity, 1.0), 1);
            case GLASS -> new Material(kind, c, 0, or(specular, 0.6), or(shininess, 250), 0, or(ior, 1.5));
        };
    }

    /** A material of the given kind and colour with every other coefficient at its default. */
    public static Material of(MaterialKind kind, Rgb color) {
        return of(kind, color, null, null, null, null, null);
    }

    private static double or(Double value, double fallback) {
        return value != null ? value : fallback;
    }
}
