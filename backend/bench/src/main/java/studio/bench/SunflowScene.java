package studio.bench;

import java.util.LinkedHashMap;
import java.util.Map;

import studio.engine.material.Material;
import studio.engine.math.Rgb;
import studio.engine.math.Rotation;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;

/**
 * A resolved scene as calls of Sunflow's API ({@link SunflowScript}): the same geometry, camera and
 * lights, and the nearest Sunflow shader per material. Sunflow is a timing peer, not an image peer:
 * <ul>
 * <li>its point lights always fall off (power / (4 pi d^2)) and its diffuse shader divides by pi, so a
 *     light's power is 4 pi^2 x intensity, times the squared distance to the camera's target for our
 *     lights without fall-off: right there, darker beyond, brighter nearer;</li>
 * <li>the ambient term is Sunflow's "fake" GI engine with sky = ground = ambient;</li>
 * <li>plastic is "phong" (Phong's reflected-ray lobe, not Blinn's; no glossy rays), metal is
 *     "shiny_diffuse" (diffuse and a Fresnel-weighted mirror reflection, no highlight), glass is
 *     "glass" (Schlick's Fresnel, tinted shadows), mirror "mirror", chalk "diffuse", flat "constant".</li>
 * </ul>
 * The camera is matched pixel for pixel (see {@link #lens}): Sunflow's pinhole spreads tan(fov/2)
 * over W - 1 pixels, not W, and samples half a pixel off ours, so its fov, aspect and shift differ.
 */
public final class SunflowScene {

    private SunflowScene() {
    }

    /**
     * @param aaLevel Sunflow's anti-aliasing level: 4^level samples per pixel (0: one, 2: sixteen)
     */
    public static SunflowScript of(ResolvedScene scene, int aaLevel, int threads) {
        SunflowScript s = new SunflowScript();
        camera(s, scene);
        s.param("threads", threads).param("threads.lowPriority", false)
                .param("resolutionX", scene.width()).param("resolutionY", scene.height())
                .param("aa.min", aaLevel).param("aa.max", aaLevel).param("filter", "box")
                .param("depths.reflection", scene.maxDepth()).param("depths.refraction", scene.maxDepth())
                .param("camera", "camera");
        if (scene.ambient() > 0 && !scene.lights().isEmpty()) {
            Rgb sky = new Rgb(scene.ambient(), scene.ambient(), scene.ambient());
            s.param("gi.engine", "fake").color("gi.fake.sky", sky).color("gi.fake.ground", sky)
                    .vector("gi.fake.up", scene.camera().up());
        }
        s.options("::options");

        if (!scene.background().isBlack()) {
            s.color("color", scene.background()).shader("background.shader", "constant")
                    .geometry("background", "background").strings("shaders", "background.shader")
                    .instance("background.instance", "background");
        }
        int n = 0;
        for (ResolvedScene.Light light : scene.lights()) {
            if (light.soft()) {
                throw new IllegalArgumentException("the Sunflow export has point lights only, not sphere or area lights");
            }
            double scale = 4 * Math.PI * Math.PI;
            if (!light.falloff()) {
                double d = light.position().minus(scene.camera().lookAt()).length();
                scale *= Math.max(d * d, 1e-12);
            }
            s.point("center", light.position()).color("power", light.color().times(light.intensity() * scale))
                    .light("light" + n++, "point");
        }

        Map<Material, String> shaders = new LinkedHashMap<>();
        boolean unitSphere = false;
        n = 0;
        for (ResolvedScene.Shape shape : scene.objects()) {
            String shader = shaders.get(shape.material());
            if (shader == null) {
                shader = "shader" + shaders.size();
                shaders.put(shape.material(), shader);
                shader(s, shader, shape.material());
            }
            String name = "object" + n++;
            if (shape instanceof ResolvedScene.Sphere sphere) {
                if (!unitSphere) {
                    s.geometry("sphere", "sphere");
                    unitSphere = true;
                }
                double r = sphere.radius();
                Vec3 c = sphere.center();
                s.matrix("transform", new double[] {r, 0, 0, c.x(), 0, r, 0, c.y(), 0, 0, r, c.z(), 0, 0, 0, 1})
                        .strings("shaders", shader).instance(name, "sphere");
            } else if (shape instanceof ResolvedScene.Box box) {
                Vec3 h = box.size().times(0.5);
                s.floats("points", "point", "vertex", new double[] {-h.x(), -h.y(), -h.z(), h.x(), h.y(), h.z()})
                        .geometry(name + ".geometry", "box")
                        .matrix("transform", boxTransform(box)).strings("shaders", shader)
                        .instance(name, name + ".geometry");
            } else if (shape instanceof ResolvedScene.Plane plane) {
                s.point("center", plane.point()).vector("normal", plane.normal())
                        .geometry(name + ".geometry", "plane").strings("shaders", shader)
                        .instance(name, name + ".geometry");
            } else {
                ResolvedScene.Mesh mesh = (ResolvedScene.Mesh) shape;
                mesh(s, name, mesh.mesh(), shader, transform(mesh.position(), mesh.rotationDegrees(), mesh.scale()));
            }
        }
        return s;
    }

    /** The pinhole camera, its fov, aspect and shift set so that its pixel centres are ours. */
    static void camera(SunflowScript s, ResolvedScene scene) {
        ResolvedScene.Camera c = scene.camera();
        double[] lens = lens(c.fovDegrees(), scene.width(), scene.height());
        s.lookAt("transform", c.position(), c.lookAt(), c.up()).param("fov", lens[0]).param("aspect", lens[1])
                .param("shift.x", lens[2]).param("shift.y", lens[3]).camera("camera", "pinhole");
    }

    /**
     * Sunflow's pinhole {@code fov} (horizontal, degrees), {@code aspect}, {@code shift.x} and
     * {@code shift.y} for our vertical fov. Sunflow samples pixel (i, j) at x = i + 1/2, y = H - j - 1/2
     * and maps x to shift.x - a + 2 a x / (W - 1) with a = tan(fov/2) (y likewise with a / aspect);
     * ours sends pixel i to (2 (i + 1/2) / W - 1) t with t = tan(vfov/2) W/H. They agree when
     * a = t (W - 1) / W and shift.x = -t / W, and vertically with tan(vfov/2) and H.
     *
     * @return {fov, aspect, shift.x, shift.y}
     */
    static double[] lens(double verticalFovDegrees, int width, int height) {
        double tanV = Math.tan(Math.toRadians(verticalFovDegrees) / 2);
        double tanH = tanV * width / height;
        double au = tanH * (width - 1) / width;
        double av = tanV * (height - 1) / height;
        return new double[] {Math.toDegrees(2 * Math.atan(au)), au / av, -tanH / width, -tanV / height};
    }

    /** Translation times our rotation matrix (Rx Ry Rz), row-major; the box's size is in its points. */
    static double[] boxTransform(ResolvedScene.Box box) {
        return transform(box.center(), box.rotationDegrees(), 1);
    }

    /**
     * The engine's placement of a box or mesh as a row-major instance transform: translation times
     * our rotation matrix (Rx Ry Rz) times a uniform scale, so a point is scaled, then rotated
     * (about z first), then moved.
     */
    static double[] transform(Vec3 translation, Vec3 rotationDegrees, double scale) {
        Rotation r = Rotation.fromEulerDegrees(rotationDegrees);
        Vec3 c = translation;
        return new double[] {
                scale * r.get(0, 0), scale * r.get(0, 1), scale * r.get(0, 2), c.x(),
                scale * r.get(1, 0), scale * r.get(1, 1), scale * r.get(1, 2), c.y(),
                scale * r.get(2, 0), scale * r.get(2, 1), scale * r.get(2, 2), c.z(),
                0, 0, 0, 1};
    }

    /**
     * An object-space triangle mesh: Sunflow's "triangle_mesh" (with per-vertex normals if it has
     * them), instanced with {@code transform}. Sunflow turns normals by the instance's
     * inverse transpose, which for a uniform scale is the rotation.
     */
    static void mesh(SunflowScript s, String name, MeshData mesh, String shader, double[] transform) {
        s.floats("points", "point", "vertex", mesh.positions());
        if (mesh.hasNormals()) {
            s.floats("normals", "vector", "vertex", mesh.normals());
        }
        s.ints("triangles", mesh.indices())
                .geometry(name + ".geometry", "triangle_mesh")
                .matrix("transform", transform).strings("shaders", shader)
                .instance(name, name + ".geometry");
    }

    static void shader(SunflowScript s, String name, Material m) {
        Rgb c = m.color();
        switch (m.kind()) {
            case FLAT -> s.color("color", c).shader(name, "constant");
            case CHALK -> s.color("diffuse", c.times(m.diffuse())).shader(name, "diffuse");
            case PLASTIC -> s.color("diffuse", c.times(m.diffuse())).color("specular", Rgb.WHITE.times(m.specular()))
                    .param("power", m.shininess()).param("samples", 0).shader(name, "phong");
            case METAL -> s.color("diffuse", c.times(m.diffuse())).param("shiny", m.reflectivity())
                    .shader(name, "shiny_diffuse");
            case MIRROR -> s.color("color", c.times(m.reflectivity())).shader(name, "mirror");
            case GLASS -> s.param("eta", m.ior()).color("color", c).shader(name, "glass");
        }
    }
}
