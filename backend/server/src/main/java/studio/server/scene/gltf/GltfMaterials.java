package studio.server.scene.gltf;

import java.util.Set;

import tools.jackson.databind.JsonNode;

import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;

/**
 * glTF's metallic-roughness materials onto the scene format's six, in this order (docs/scene-format.md
 * has the table):
 * <ul>
 * <li>a non-black {@code emissiveFactor} (times {@code KHR_materials_emissive_strength}) -> flat, in
 * that colour;</li>
 * <li>{@code KHR_materials_transmission}'s {@code transmissionFactor} of 0.5 or more -> glass, tinted by
 * the base colour, its index from {@code KHR_materials_ior} (1.5 without);</li>
 * <li>{@code metallicFactor} of 0.5 or more -> metal, else plastic, in the base colour; the highlight's
 * Blinn-Phong exponent n from the roughness r as 2/a^2 - 2 with a = r^2 (within [1, 10000]), its strength
 * the kind's default times (n + 8)/(n0 + 8) for the default exponent n0 (at most 1), as normalised
 * Blinn-Phong keeps a lobe's energy, so that a rough surface's broad highlight does not wash its colour
 * out; and a metal's reflectivity 0.5 * (1 - r) and diffuse weight 0.15 + 0.65 * r.</li>
 * </ul>
 * glTF's colours are linear already, as the engine's are. A primitive without a material takes glTF's
 * default (white, metallic 1, roughness 1: a rough white metal, as three.js draws it).
 */
final class GltfMaterials {

    static final Set<String> READ_EXTENSIONS = Set.of("KHR_materials_transmission", "KHR_materials_ior",
            "KHR_materials_emissive_strength");

    /** A material and its base colour texture (or null). */
    record Mapped(Material material, GltfTexture texture) {
    }

    private final JsonNode materials;
    private final GltfImages images;
    private final Set<String> warnings;

    GltfMaterials(JsonNode root, GltfImages images, Set<String> warnings) {
        this.materials = GltfJson.array(root, "materials", "");
        this.images = images;
        this.warnings = warnings;
    }

    int size() {
        return materials.size();
    }

    /** Material {@code i}, or glTF's default material for -1. */
    Mapped of(int i) {
        if (i < 0) {
            return new Mapped(metallic(new Rgb(1, 1, 1), 1), null);
        }
        String path = "materials[" + i + "]";
        JsonNode m = GltfJson.element(materials, i, "materials");
        JsonNode pbr = m.path("pbrMetallicRoughness");
        String pbrPath = path + ".pbrMetallicRoughness";
        double[] base = GltfJson.numbers(pbr, "baseColorFactor", 4, new double[] {1, 1, 1, 1}, pbrPath);
        Rgb color = unit(base, pbrPath + ".baseColorFactor");
        double metallic = clamp(GltfJson.number(pbr, "metallicFactor", 1, pbrPath), 0, 1);
        double roughness = clamp(GltfJson.number(pbr, "roughnessFactor", 1, pbrPath), 0, 1);
        String alphaMode = GltfJson.string(m, "alphaMode", path);
        if (alphaMode != null && !alphaMode.equals("OPAQUE")) {
            warnings.add(path + ": alphaMode " + alphaMode + " is drawn opaque");
        }
        for (String texture : new String[] {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
            if (!m.path(texture).isMissingNode()) {
                warnings.add(path + ": its " + texture + " is not drawn");
            }
        }
        if (!pbr.path("metallicRoughnessTexture").isMissingNode()) {
            warnings.add(pbrPath + ": its metallicRoughnessTexture is not drawn (the factors are)");
        }
        JsonNode extensions = m.path("extensions");
        for (String name : extensions.propertyNames()) {
            if (!READ_EXTENSIONS.contains(name)) {
                warnings.add(path + ": the extension " + name + " is not drawn");
            }
        }
        GltfTexture texture = baseColorTexture(pbr.path("baseColorTexture"), pbrPath + ".baseColorTexture");
        double[] emissive = GltfJson.numbers(m, "emissiveFactor", 3, new double[] {0, 0, 0}, path);
        double strength = GltfJson.number(extensions.path("KHR_materials_emissive_strength"), "emissiveStrength", 1,
                path + ".extensions.KHR_materials_emissive_strength");
        Rgb glow = unit(emissive, path + ".emissiveFactor").times(Math.max(0, strength));
        if (glow.max() > 0) {
            return new Mapped(MaterialDefaults.of(MaterialKind.FLAT, glow), null);
        }
        double transmission = GltfJson.number(extensions.path("KHR_materials_transmission"), "transmissionFactor", 0,
                path + ".extensions.KHR_materials_transmission");
        if (transmission >= 0.5) {
            double ior = GltfJson.number(extensions.path("KHR_materials_ior"), "ior", 1.5,
                    path + ".extensions.KHR_materials_ior");
            if (ior < 1) {
                warnings.add(path + ": KHR_materials_ior's ior " + ior + " is below 1; 1.5 is used");
                ior = 1.5;
            }
            return new Mapped(MaterialDefaults.of(MaterialKind.GLASS, color, null, null, null, null, ior), texture);
        }
        return new Mapped(metallic >= 0.5 ? metallic(color, roughness)
                : plastic(color, roughness), texture);
    }

    /**
     * A metal of roughness r: the smoother, the more it mirrors (reflectivity 0.5 * (1 - r)); the rougher,
     * the more its colour shows diffusely (diffuse 0.15 + 0.65 * r), as a rough metal scatters its
     * tinted reflection every way: a fully rough one has a plastic's diffuse weight, in its own colour.
     */
    private static Material metallic(Rgb color, double roughness) {
        double n = shininess(roughness);
        return MaterialDefaults.of(MaterialKind.METAL, color, 0.15 + 0.65 * roughness,
                highlight(MaterialKind.METAL, n), n, 0.5 * (1 - roughness), null);
    }

    private static Material plastic(Rgb color, double roughness) {
        double n = shininess(roughness);
        return MaterialDefaults.of(MaterialKind.PLASTIC, color, null, highlight(MaterialKind.PLASTIC, n), n, null, null);
    }

    /**
     * The highlight's strength at exponent n: the kind's default strength at its default exponent,
     * scaled as normalised Blinn-Phong's (n + 8)/(8 pi) scales a lobe, at most 1. A broad lobe (rough,
     * n near 1) then adds about as much light as the default's narrow one, not six times as much.
     */
    static double highlight(MaterialKind kind, double n) {
        Material defaults = MaterialDefaults.of(kind, null);
        return Math.min(1, defaults.specular() * (n + 8) / (defaults.shininess() + 8));
    }

    /** The Blinn-Phong exponent of a GGX roughness r: 2/a^2 - 2 with a = r^2, within [1, 10000]. */
    static double shininess(double roughness) {
        double a = roughness * roughness;
        return a == 0 ? 10000 : clamp(2 / (a * a) - 2, 1, 10000);
    }

    private static double clamp(double v, double min, double max) {
        return Math.max(min, Math.min(max, v));
    }

    /** A colour's first three factors, each clamped to [0, 1] (with a warning if one was outside). */
    private Rgb unit(double[] factors, String path) {
        for (int c = 0; c < 3; c++) {
            if (factors[c] < 0 || factors[c] > 1) {
                warnings.add(path + ": its factors are clamped to [0, 1]");
                break;
            }
        }
        return new Rgb(clamp(factors[0], 0, 1), clamp(factors[1], 0, 1), clamp(factors[2], 0, 1));
    }

    private GltfTexture baseColorTexture(JsonNode info, String path) {
        if (info.isMissingNode()) {
            return null;
        }
        if (!info.isObject()) {
            throw GltfJson.bad(path, "must be an object");
        }
        long texCoord = GltfJson.whole(info, "texCoord", 0, Integer.MAX_VALUE, 0, path);
        if (texCoord != 0) {
            warnings.add(path + ": only TEXCOORD_0 is read, so this texture (on TEXCOORD_" + texCoord + ") is not drawn");
            return null;
        }
        if (!info.path("extensions").isEmpty()) {
            warnings.add(path + ": texture transforms and other texture extensions are not applied");
        }
        return images.texture(GltfJson.index(info, "index", images.textureCount(), "textures", path));
    }
}
