package studio.bench;

import java.util.ArrayList;
import java.util.List;

import studio.engine.light.AreaLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.compiling.Colors;
import studio.server.scene.compiling.MaterialMapping;
import studio.server.scene.format.CameraDto;
import studio.server.scene.format.LightDto;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.RenderDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneDto;

/**
 * A scene file with every default applied, in the terms the exporters need: positions in world
 * space, colours in linear light, materials with their resolved coefficients (from the engine's
 * {@link MaterialDefaults}, as the server's MaterialMapping maps them). The image size is the
 * benchmark's, not the file's.
 */
public record ResolvedScene(int width, int height, Camera camera, Rgb background, double ambient, int maxDepth,
                            List<Light> lights, List<Shape> objects) {

    /** A perspective camera; {@code fovDegrees} is vertical, as in the scene format. */
    public record Camera(Vec3 position, Vec3 lookAt, Vec3 up, double fovDegrees) {
    }

    /**
     * A light: colour (linear) times intensity; divided by the squared distance if {@code falloff}.
     * A point light has {@code radius} 0 and no {@code area}; a sphere light a radius above 0; an
     * area light its rectangle.
     */
    public record Light(Vec3 position, Rgb color, double intensity, boolean falloff, double radius, Area area) {

        /** A point light. */
        public Light(Vec3 position, Rgb color, double intensity, boolean falloff) {
            this(position, color, intensity, falloff, 0, null);
        }

        /** Whether it has a size (and so soft shadows). */
        public boolean soft() {
            return radius > 0 || area != null;
        }
    }

    /** An area light's rectangle: width along {@code widthAxis}, height along {@code heightAxis} (unit), facing {@code normal}. */
    public record Area(double width, double height, Vec3 widthAxis, Vec3 heightAxis, Vec3 normal, boolean twoSided) {
    }

    /** A scene object with its material. */
    public sealed interface Shape {
        Material material();
    }

    public record Sphere(Vec3 center, double radius, Material material) implements Shape {
    }

    /** A box: centre, full edge lengths, Euler angles in degrees (three.js order XYZ). */
    public record Box(Vec3 center, Vec3 size, Vec3 rotationDegrees, Material material) implements Shape {
    }

    /** An infinite plane through {@code point}; {@code normal} has unit length. */
    public record Plane(Vec3 point, Vec3 normal, Material material) implements Shape {
    }

    /**
     * A triangle mesh in object space (the engine's {@link MeshData}, as read from the scene's OBJ),
     * placed as the engine's TriangleMesh places it: scaled uniformly, then rotated (Euler degrees,
     * three.js order XYZ, as a box), then moved to {@code position}.
     */
    public record Mesh(MeshData mesh, Vec3 position, double scale, Vec3 rotationDegrees, Material material)
            implements Shape {
    }

    /** The material of every object but planes in the silhouette variant: flat white. */
    public static final Material MASK_MATERIAL = MaterialDefaults.of(MaterialKind.FLAT, Rgb.WHITE);
    /** The material of planes in the silhouette variant: flat black, so they hide what is behind them but
     *  the silhouettes of the objects on them still show. */
    public static final Material MASK_PLANE_MATERIAL = MaterialDefaults.of(MaterialKind.FLAT, Rgb.BLACK);

    /** As {@link #of(SceneDto, int, int, MeshFiles)} for a scene whose meshes are all inline. */
    public static ResolvedScene of(SceneDto dto, int width, int height) {
        return of(dto, width, height, MeshFiles.none());
    }

    /**
     * The scene at the given image size, with the scene format's defaults for every field left out;
     * a mesh's {@code file} is read from {@code meshFiles}.
     *
     * @throws IllegalArgumentException if a mesh has no OBJ text, or it cannot be read or parsed
     */
    public static ResolvedScene of(SceneDto dto, int width, int height, MeshFiles meshFiles) {
        CameraDto c = dto.camera() != null ? dto.camera() : new CameraDto(null, null, null, null);
        Camera camera = new Camera(vec(or(c.position(), SceneDefaults.CAMERA_POSITION)),
                vec(or(c.lookAt(), SceneDefaults.CAMERA_LOOK_AT)), vec(or(c.up(), SceneDefaults.CAMERA_UP)),
                or(c.fov(), SceneDefaults.CAMERA_FOV_DEGREES));
        RenderDto render = dto.render() != null ? dto.render() : new RenderDto(null, null, null, null);

        List<Light> lights = new ArrayList<>();
        if (dto.lights() == null) {
            lights.add(new Light(vec(SceneDefaults.LIGHT_POSITION), Colors.linear(SceneDefaults.LIGHT_COLOR),
                    SceneDefaults.LIGHT_INTENSITY, false));
        } else {
            for (LightDto light : dto.lights()) {
                lights.add(light(light));
            }
        }

        List<Shape> objects = new ArrayList<>();
        for (ObjectDto o : dto.objects()) {
            Material m = MaterialMapping.of(o.material());
            if (o instanceof ObjectDto.Sphere s) {
                objects.add(new Sphere(vec(or(s.center(), SceneDefaults.SPHERE_CENTER)),
                        or(s.radius(), SceneDefaults.SPHERE_RADIUS), m));
            } else if (o instanceof ObjectDto.Box b) {
                objects.add(new Box(vec(or(b.center(), SceneDefaults.BOX_CENTER)), vec(or(b.size(), SceneDefaults.BOX_SIZE)),
                        vec(or(b.rotation(), SceneDefaults.ORIGIN)), m));
            } else if (o instanceof ObjectDto.Mesh x) {
                if ((x.obj() == null) == (x.file() == null)) {
                    throw new IllegalArgumentException("a mesh needs either its OBJ text in \"obj\" or a \"file\"");
                }
                MeshData data = ObjReader.parse(x.obj() != null ? x.obj() : meshFiles.read(x.file()));
                objects.add(new Mesh(data, vec(or(x.position(), SceneDefaults.ORIGIN)),
                        or(x.scale(), SceneDefaults.MESH_SCALE), vec(or(x.rotation(), SceneDefaults.ORIGIN)), m));
            } else {
                ObjectDto.Plane p = (ObjectDto.Plane) o;
                objects.add(new Plane(vec(or(p.point(), SceneDefaults.ORIGIN)),
                        vec(or(p.normal(), SceneDefaults.PLANE_NORMAL)).normalized(), m));
            }
        }
        return new ResolvedScene(width, height, camera, Colors.linear(or(dto.background(), SceneDefaults.BACKGROUND)),
                or(dto.ambient(), SceneDefaults.AMBIENT), or(render.maxDepth(), SceneDefaults.MAX_DEPTH), lights, objects);
    }

    private static Light light(LightDto light) {
        if (light instanceof LightDto.Area a) {
            List<Double> size = or(a.size(), SceneDefaults.AREA_LIGHT_SIZE);
            AreaLight engine = new AreaLight(vec(or(a.position(), SceneDefaults.LIGHT_POSITION)), size.get(0), size.get(1),
                    vec(or(a.lookAt(), SceneDefaults.AREA_LIGHT_LOOK_AT)), Rgb.WHITE, 1, false,
                    Boolean.TRUE.equals(a.twoSided()));
            return new Light(engine.position(), Colors.linear(or(a.color(), SceneDefaults.LIGHT_COLOR)),
                    or(a.intensity(), SceneDefaults.LIGHT_INTENSITY), Boolean.TRUE.equals(a.falloff()), 0,
                    new Area(engine.width(), engine.height(), engine.widthAxis(), engine.heightAxis(), engine.normal(),
                            engine.twoSided()));
        }
        LightDto.Point p = (LightDto.Point) light;
        return new Light(vec(or(p.position(), SceneDefaults.LIGHT_POSITION)),
                Colors.linear(or(p.color(), SceneDefaults.LIGHT_COLOR)),
                or(p.intensity(), SceneDefaults.LIGHT_INTENSITY), Boolean.TRUE.equals(p.falloff()),
                or(p.radius(), SceneDefaults.LIGHT_RADIUS), null);
    }

    /**
     * The silhouette variant: every object flat white but planes flat black, no lights, a black
     * background. Every renderer draws it as a white-on-black mask of the scene's bounded objects
     * (a ground plane would otherwise fill the image and hide every silhouette on it).
     */
    public ResolvedScene asMask() {
        List<Shape> white = new ArrayList<>();
        for (Shape s : objects) {
            white.add(withMaterial(s, s instanceof Plane ? MASK_PLANE_MATERIAL : MASK_MATERIAL));
        }
        return new ResolvedScene(width, height, camera, Rgb.BLACK, ambient, maxDepth, List.of(), white);
    }

    /** The same shape with another material. */
    static Shape withMaterial(Shape s, Material m) {
        if (s instanceof Sphere x) {
            return new Sphere(x.center(), x.radius(), m);
        }
        if (s instanceof Box x) {
            return new Box(x.center(), x.size(), x.rotationDegrees(), m);
        }
        if (s instanceof Plane x) {
            return new Plane(x.point(), x.normal(), m);
        }
        Mesh x = (Mesh) s;
        return new Mesh(x.mesh(), x.position(), x.scale(), x.rotationDegrees(), m);
    }

    public double aspect() {
        return (double) width / height;
    }

    private static Vec3 vec(List<Double> v) {
        return new Vec3(v.get(0), v.get(1), v.get(2));
    }

    private static <T> T or(T value, T fallback) {
        return value != null ? value : fallback;
    }
}
