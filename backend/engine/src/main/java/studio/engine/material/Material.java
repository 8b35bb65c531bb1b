package studio.engine.material;

import studio.engine.math.Rgb;
import studio.engine.texture.Texture;

/**
 * How a surface answers light: one of the six kinds of the scene format with its resolved
 * coefficients. Build one with {@link MaterialDefaults#of}; the integrator reads the
 * coefficients and skips every lobe whose weight is zero.
 *
 * @param color        base colour in linear light (diffuse albedo; tint of metal, mirror and glass)
 * @param diffuse      weight of the Lambertian lobe and the ambient term
 * @param specular     weight of the Blinn-Phong highlight from point lights
 * @param shininess    Blinn-Phong exponent
 * @param reflectivity weight of the mirror reflection (metal, mirror); glass uses Fresnel instead
 * @param ior          index of refraction (glass)
 * @param texture      what the colour is multiplied by over the surface (as glTF's baseColorTexture
 *                     times its baseColorFactor), or null: the colour alone
 */
public record Material(MaterialKind kind, Rgb color, double diffuse, double specular, double shininess,
                       double reflectivity, double ior, Texture texture) {

    /** An untextured material. */
    public Material(MaterialKind kind, Rgb color, double diffuse, double specular, double shininess,
                    double reflectivity, double ior) {
        this(kind, color, diffuse, specular, shininess, reflectivity, ior, null);
    }

    public Material {
        if (kind == null || color == null) {
            throw new IllegalArgumentException("material kind and colour are required");
        }
        check("diffuse", diffuse, 0, Double.MAX_VALUE);
        check("specular", specular, 0, Double.MAX_VALUE);
        check("shininess", shininess, 0, Double.MAX_VALUE);
        check("reflectivity", reflectivity, 0, 1);
        if (!(ior >= 1) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("ior must be finite and at least 1: " + ior);
        }
        if (!(color.r() >= 0 && color.g() >= 0 && color.b() >= 0) || !Double.isFinite(color.max())) {
            throw new IllegalArgumentException("colour must be finite and non-negative: " + color);
        }
    }

    private static void check(String name, double value, double min, double max) {
        if (!(value >= min && value <= max)) {
            throw new IllegalArgumentException(name + " must be in [" + min + ", " + max + "]: " + value);
        }
    }

    /** This material with its colour multiplied by {@code texture} (null: none). */
    public Material withTexture(Texture texture) {
        return new Material(kind, color, diffuse, specular, shininess, reflectivity, ior, texture);
    }
}
