package studio.bench;

import studio.engine.material.Material;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.render.RenderSettings;

/**
 * A resolved scene as POV-Ray 3.7 scene description, matched to our renderer:
 * <ul>
 * <li>Coordinates are ours, unchanged; {@code right -x*W/H} makes POV-Ray's camera right-handed,
 *     {@code angle} is the horizontal field of view worked out from our vertical one.</li>
 * <li>{@code assumed_gamma 1.0}: colours are written in linear light (as we shade), POV-Ray writes sRGB.</li>
 * <li>{@code max_trace_level} = maxDepth + 1 (POV-Ray counts the camera ray as level 1),
 *     {@code adc_bailout} = our minimum path weight.</li>
 * <li>Point lights: colour times intensity, no fall-off (as ours); with fall-off, POV-Ray's
 *     2 / (1 + (d/f)^2) with f = {@value #FADE_DISTANCE} and the colour scaled by 1 / (2 f^2),
 *     which is 1 / (d^2 + f^2): 1/d^2 to within 1e-6 relative beyond 1 mm.</li>
 * <li>Sphere and area lights: POV-Ray's {@code area_light}, an n x n grid of point lights sharing
 *     the colour, sampled as {@link AreaSampling} says (the grid, {@code adaptive 1}: corners first,
 *     subdividing only where they disagree, {@code jitter}). A sphere is a {@code circular orient}
 *     disc of its diameter, turned to face each point it lights (its silhouette); a rectangle its two
 *     edges. Both are seen through a {@code looks_like} object of colour times intensity, as ours.
 *     POV-Ray's sub-lights shine both ways and have no cosine at the light: a one-sided rectangle
 *     lights the points behind it there, and its light falls off less to the side than ours.</li>
 * <li>Finishes: {@code ambient} = diffuse x scene ambient (ours: colour x diffuse x ambient),
 *     {@code diffuse} as ours, the Blinn highlight as {@code specular} with {@code roughness} =
 *     1 / shininess (POV-Ray's specular is Blinn's half-vector lobe), {@code metallic} tints a
 *     metal's highlight with its colour, {@code reflection rgb} = colour x reflectivity.</li>
 * <li>Glass: {@code rgbf <sqrt(colour), 1>}, because POV-Ray filters at every surface crossed and
 *     we tint once, on the way in; Fresnel reflection with {@code conserve_energy}, {@code interior
 *     { ior }}. Filtered light passes shadow rays, so glass casts a light, tinted shadow as ours.</li>
 * <li>Boxes: {@code rotate z, then y, then x}: our rotation matrix is Rx Ry Rz (three.js 'XYZ'),
 *     which turns a point about z first; POV-Ray's rotate matrices are the same numbers as ours.</li>
 * <li>Meshes: {@code mesh2} in object space, then {@code scale s}, the box's rotations and
 *     {@code translate}: the engine's placement (scale, rotate XYZ, move).</li>
 * </ul>
 */
public final class PovrayScene {

    /** The fade distance that turns POV-Ray's fall-off into 1 / d^2 (see the class comment). */
    static final double FADE_DISTANCE = 1e-3;

    private PovrayScene() {
    }

    /** How POV-Ray samples a light with a size: an n x n grid, corners first or not, jittered or not. */
    public record AreaSampling(int grid, boolean adaptive, boolean jitter) {
        /** The peer benchmark's: 8 x 8, adaptive, jittered (POV-Ray's documentation's advice for speed). */
        public static final AreaSampling DEFAULT = new AreaSampling(8, true, true);
    }

    /** The whole scene as SDL text, lights with a size sampled as {@link AreaSampling#DEFAULT}. */
    public static String of(ResolvedScene scene, String title) {
        return of(scene, title, AreaSampling.DEFAULT);
    }

    /** The whole scene as SDL text, lights with a size sampled as {@code area} says. */
    public static String of(ResolvedScene scene, String title, AreaSampling area) {
        StringBuilder sdl = new StringBuilder(256 + 160 * scene.objects().size());
        sdl.append("// ").append(title.replaceAll("[\\r\\n]", " ")).append(", exported by studio-bench\n");
        sdl.append("#version 3.7;\n");
        sdl.append("global_settings { assumed_gamma 1.0 max_trace_level ").append(scene.maxDepth() + 1)
                .append(" adc_bailout ").append(Sdl.num(RenderSettings.DEFAULT_MIN_PATH_WEIGHT)).append(" }\n");
        sdl.append(camera(scene));
        sdl.append("background { color rgb ").append(Sdl.rgb(scene.background())).append(" }\n");
        for (ResolvedScene.Light light : scene.lights()) {
            sdl.append(light(light, area));
        }
        for (ResolvedScene.Shape shape : scene.objects()) {
            shape(sdl, shape, scene.ambient());
        }
        return sdl.toString();
    }

    /** A right-handed camera: {@code right -x*aspect}, horizontal {@code angle}, {@code sky} = our up. */
    static String camera(ResolvedScene scene) {
        ResolvedScene.Camera c = scene.camera();
        double angle = CameraMath.horizontalFovDegrees(c.fovDegrees(), scene.aspect());
        return "camera {\n  perspective\n  location " + Sdl.vec(c.position()) + "\n  sky " + Sdl.vec(c.up())
                + "\n  up y\n  right -x*" + Sdl.num(scene.aspect()) + "\n  angle " + Sdl.num(angle)
                + "\n  look_at " + Sdl.vec(c.lookAt()) + "\n}\n";
    }

    static String light(ResolvedScene.Light light) {
        return light(light, AreaSampling.DEFAULT);
    }

    static String light(ResolvedScene.Light light, AreaSampling area) {
        Rgb power = light.color().times(light.intensity());
        String size = light.soft() ? areaLight(light, area) : "";
        if (!light.falloff()) {
            return "light_source { " + Sdl.vec(light.position()) + " color rgb " + Sdl.rgb(power) + size + " }\n";
        }
        double scale = 1 / (2 * FADE_DISTANCE * FADE_DISTANCE);
        return "light_source { " + Sdl.vec(light.position()) + " color rgb " + Sdl.rgb(power.times(scale))
                + " fade_distance " + Sdl.num(FADE_DISTANCE) + " fade_power 2" + size + " }\n";
    }

    /** A light's {@code area_light} and {@code looks_like} (relative to its position), after its colour. */
    private static String areaLight(ResolvedScene.Light light, AreaSampling area) {
        Rgb power = light.color().times(light.intensity());
        String look = "texture { pigment { rgb " + Sdl.rgb(power) + " } finish { ambient 0 diffuse 0 emission 1 } }";
        String grid = ", " + area.grid() + ", " + area.grid() + (area.adaptive() ? " adaptive 1" : "")
                + (area.jitter() ? " jitter" : "");
        if (light.area() == null) {
            double d = 2 * light.radius();
            return "\n  area_light <" + Sdl.num(d) + ", 0, 0>, <0, 0, " + Sdl.num(d) + ">" + grid + " circular orient"
                    + "\n  looks_like { sphere { <0, 0, 0>, " + Sdl.num(light.radius()) + " " + look + " } }";
        }
        ResolvedScene.Area a = light.area();
        Vec3 w = a.widthAxis().times(a.width()), h = a.heightAxis().times(a.height());
        Vec3 c00 = w.plus(h).times(-0.5), c10 = w.minus(h).times(0.5), c11 = w.plus(h).times(0.5),
                c01 = h.minus(w).times(0.5);
        return "\n  area_light " + Sdl.vec(w) + ", " + Sdl.vec(h) + grid
                + "\n  looks_like { union { triangle { " + Sdl.vec(c00) + ", " + Sdl.vec(c10) + ", " + Sdl.vec(c11)
                + " } triangle { " + Sdl.vec(c00) + ", " + Sdl.vec(c11) + ", " + Sdl.vec(c01) + " } " + look + " } }";
    }

    static void shape(StringBuilder sdl, ResolvedScene.Shape shape, double ambient) {
        if (shape instanceof ResolvedScene.Sphere s) {
            sdl.append("sphere { ").append(Sdl.vec(s.center())).append(", ").append(Sdl.num(s.radius()));
        } else if (shape instanceof ResolvedScene.Box b) {
            Vec3 half = b.size().times(0.5);
            sdl.append("box { ").append(Sdl.vec(half.negated())).append(", ").append(Sdl.vec(half));
            rotate(sdl, b.rotationDegrees());
            sdl.append(" translate ").append(Sdl.vec(b.center()));
        } else if (shape instanceof ResolvedScene.Plane p) {
            sdl.append("plane { ").append(Sdl.vec(p.normal())).append(", ").append(Sdl.num(p.normal().dot(p.point())));
        } else {
            ResolvedScene.Mesh m = (ResolvedScene.Mesh) shape;
            mesh(sdl, m.mesh());
            sdl.append("\n  scale ").append(Sdl.num(m.scale()));
            rotate(sdl, m.rotationDegrees());
            sdl.append(" translate ").append(Sdl.vec(m.position()));
        }
        sdl.append("\n  ").append(material(shape.material(), ambient)).append(" }\n");
    }

    /**
     * Our rotation (Euler degrees, Rx Ry Rz) as POV-Ray rotations: about z first, then y, then x
     * (see {@code RotationOrderTest}); zero angles are left out.
     */
    static void rotate(StringBuilder sdl, Vec3 degrees) {
        if (degrees.z() != 0) {
            sdl.append(" rotate z*").append(Sdl.num(degrees.z()));
        }
        if (degrees.y() != 0) {
            sdl.append(" rotate y*").append(Sdl.num(degrees.y()));
        }
        if (degrees.x() != 0) {
            sdl.append(" rotate x*").append(Sdl.num(degrees.x()));
        }
    }

    /**
     * An object-space triangle mesh as {@code mesh2 { vertex_vectors [normal_vectors] face_indices }},
     * without its transform and closing brace (they follow). A vertex's normal has the vertex's
     * index, so the face indices serve both.
     */
    static void mesh(StringBuilder sdl, MeshData mesh) {
        int n = mesh.vertexCount();
        sdl.append("mesh2 {\n  vertex_vectors { ").append(n);
        appendTriples(sdl, mesh.positions());
        sdl.append(" }");
        if (mesh.hasNormals()) {
            sdl.append("\n  normal_vectors { ").append(n);
            appendTriples(sdl, mesh.normals());
            sdl.append(" }");
        }
        sdl.append("\n  face_indices { ").append(mesh.triangleCount());
        int[] idx = mesh.indices();
        for (int i = 0; i < idx.length; i += 3) {
            sdl.append(i % 24 == 0 ? ",\n    <" : ", <").append(idx[i]).append(',').append(idx[i + 1]).append(',')
                    .append(idx[i + 2]).append('>');
        }
        sdl.append(" }");
    }

    private static void appendTriples(StringBuilder sdl, double[] v) {
        for (int i = 0; i < v.length; i += 3) {
            sdl.append(i % 12 == 0 ? ",\n    <" : ", <").append(Sdl.num(v[i])).append(',').append(Sdl.num(v[i + 1]))
                    .append(',').append(Sdl.num(v[i + 2])).append('>');
        }
    }

    /** A texture (and for glass an interior) that shades as our material does. */
    static String material(Material m, double ambient) {
        Rgb c = m.color();
        String roughness = m.shininess() > 0 ? " roughness " + Sdl.num(1 / m.shininess()) : "";
        return switch (m.kind()) {
            case FLAT -> "texture { pigment { rgb " + Sdl.rgb(c) + " } finish { ambient 1 diffuse 0 } }";
            case CHALK -> "texture { pigment { rgb " + Sdl.rgb(c) + " } finish { ambient " + Sdl.num(m.diffuse() * ambient)
                    + " diffuse " + Sdl.num(m.diffuse()) + " } }";
            case PLASTIC -> "texture { pigment { rgb " + Sdl.rgb(c) + " } finish { ambient "
                    + Sdl.num(m.diffuse() * ambient) + " diffuse " + Sdl.num(m.diffuse()) + " specular "
                    + Sdl.num(m.specular()) + roughness + " } }";
            case METAL -> "texture { pigment { rgb " + Sdl.rgb(c) + " } finish { ambient "
                    + Sdl.num(m.diffuse() * ambient) + " diffuse " + Sdl.num(m.diffuse()) + " specular "
                    + Sdl.num(m.specular()) + roughness + " metallic reflection { rgb "
                    + Sdl.rgb(c.times(m.reflectivity())) + " } } }";
            case MIRROR -> "texture { pigment { rgb " + Sdl.rgb(c) + " } finish { ambient 0 diffuse 0 reflection { rgb "
                    + Sdl.rgb(c.times(m.reflectivity())) + " } } }";
            case GLASS -> glass(m, roughness);
        };
    }

    /**
     * Glass: filtered pigment (sqrt of the tint, see the class comment), Fresnel reflection with the
     * interior's index. The highlight is on the outside only ({@code interior_texture} has none), as ours.
     */
    private static String glass(Material m, String roughness) {
        Rgb c = m.color();
        String pigment = "pigment { rgbf <" + Sdl.num(Math.sqrt(c.r())) + ", " + Sdl.num(Math.sqrt(c.g())) + ", "
                + Sdl.num(Math.sqrt(c.b())) + ", 1> }";
        String reflection = "reflection { 0, 1 fresnel on } conserve_energy";
        return "texture { " + pigment + " finish { ambient 0 diffuse 0 specular " + Sdl.num(m.specular()) + roughness
                + " " + reflection + " } }\n  interior_texture { " + pigment + " finish { ambient 0 diffuse 0 "
                + reflection + " } }\n  interior { ior " + Sdl.num(m.ior()) + " }";
    }
}
