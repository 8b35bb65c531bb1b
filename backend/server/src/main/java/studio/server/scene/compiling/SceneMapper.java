package studio.server.scene.compiling;

import java.util.ArrayList;
import java.util.List;

import studio.engine.camera.Camera;
import studio.engine.geometry.Box;
import studio.engine.geometry.Plane;
import studio.engine.geometry.Shape;
import studio.engine.geometry.Sphere;
import studio.engine.geometry.TriangleMesh;
import studio.engine.light.PointLight;
import studio.engine.material.Material;
import studio.engine.material.MaterialDefaults;
import studio.engine.material.MaterialKind;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshData;
import studio.engine.mesh.ObjReader;
import studio.engine.mesh.TooManyTrianglesException;
import studio.engine.render.RenderSettings;
import studio.engine.sampler.RegularSampler;
import studio.engine.sampler.Sampler;
import studio.engine.sampler.SobolSampler;
import studio.engine.scene.Scene;
import studio.engine.scene.SceneObject;
import studio.server.scene.format.CameraDto;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.ImageDto;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.LightDto;
import studio.server.scene.format.MaterialDto;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.RenderDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.format.SceneNames;

/**
 * Maps a validated scene DTO onto the engine, in the one place each DTO type meets its engine
 * type: fills in defaults, checks the configured limits and the rules that span fields, and
 * reports every problem by its JSON path before anything is rendered.
 *
 * <p>The memory mapping takes is asked of a {@link MemoryGate} first: {@value #BYTES_PER_OBJECT}
 * bytes an object for its engine shape, material and place in the scene (measured over 100,000 of
 * each kind, what the compiled scene keeps: 393 for a rotated box, the largest, 233 for a sphere)
 * and the scene BVH's build (about 150 while it runs), and for meshes whatever the OBJ reader and
 * the mesh's BVH build ask for as they go.
 */
public final class SceneMapper {

    static final long BYTES_PER_OBJECT = 640;

    private final SceneLimits limits;
    private final MeshCache meshes;

    public SceneMapper(SceneLimits limits) {
        this(limits, MeshCache.none());
    }

    /** @param meshes meshes already read and built, reused when a scene has them unchanged */
    public SceneMapper(SceneLimits limits, MeshCache meshes) {
        this.limits = limits;
        this.meshes = meshes;
    }

    /** As {@link #map(SceneDto, int, MeshFiles)}, with no mesh files (inline meshes only). */
    public CompiledScene map(SceneDto dto, int threads) {
        return map(dto, threads, MeshFiles.none());
    }

    /** As {@link #map(SceneDto, int, MeshFiles, MemoryGate)}, without a memory limit. */
    public CompiledScene map(SceneDto dto, int threads, MeshFiles meshFiles) {
        return map(dto, threads, meshFiles, MemoryGate.UNLIMITED);
    }

    /**
     * @param threads    worker threads for the render (0: all cores); not part of the scene format
     * @param meshFiles  where a mesh's {@code file} is read from
     * @param memory     asked before the engine objects and the meshes' arrays are allocated
     * @throws InvalidSceneException listing every problem found
     */
    public CompiledScene map(SceneDto dto, int threads, MeshFiles meshFiles, MemoryGate memory) {
        Problems problems = new Problems();
        ImageDto image = dto.image() != null ? dto.image() : new ImageDto(null, null, null, null);
        int width = or(image.width(), SceneDefaults.WIDTH);
        int height = or(image.height(), SceneDefaults.HEIGHT);
        problems.atMost("image.width", width, limits.maxWidth());
        problems.atMost("image.height", height, limits.maxHeight());

        RenderDto render = dto.render() != null ? dto.render() : new RenderDto(null, null, null, null);
        int samples = or(render.samples(), SceneDefaults.SAMPLES);
        int maxDepth = or(render.maxDepth(), SceneDefaults.MAX_DEPTH);
        String samplerName = or(render.sampler(), SceneDefaults.SAMPLER);
        problems.atMost("render.samples", samples, limits.maxSamples());
        problems.atMost("render.maxDepth", maxDepth, limits.maxDepth());
        long pixelSamples = (long) width * height * samples;
        if (pixelSamples > limits.maxPixelSamples() && width <= limits.maxWidth() && height <= limits.maxHeight()
                && samples <= limits.maxSamples()) {
            problems.add("render.samples", String.format(java.util.Locale.ROOT, "%d x %d pixels x %d samples = %,d "
                    + "samples, more than this server's render budget of %,d samples per render "
                    + "(studio.limits.max-pixel-samples); lower render.samples or the image size", width, height,
                    samples, pixelSamples, limits.maxPixelSamples()));
        }
        Sampler sampler = problems.attempt("render.samples", () -> Sampler.of(samplerName, samples));
        // adaptive sampling is the default with sobol, the method that wins the speed-against-accuracy chart
        double adaptive = or(render.adaptive(), sampler instanceof SobolSampler ? SceneDefaults.ADAPTIVE : 0.0);
        if (adaptive > 0 && sampler instanceof RegularSampler) {
            problems.add("render.adaptive", "cannot be used with the regular sampler, which would put every batch "
                    + "of samples on the same grid; choose another sampler or set it to 0");
        }

        List<ObjectDto> objectDtos = dto.objects();
        problems.atMost("objects", objectDtos.size(), limits.maxObjects(), "objects");
        memory.reserve(BYTES_PER_OBJECT * Math.min(objectDtos.size(), limits.maxObjects()));
        List<SceneObject> objects = new ArrayList<>();
        int triangles = 0;
        for (int i = 0; i < objectDtos.size() && i < limits.maxObjects(); i++) {
            ObjectDto o = objectDtos.get(i);
            String path = "objects[" + i + "]";
            Shape shape;
            if (o instanceof ObjectDto.Mesh mesh) {
                String text = meshText(mesh, path, meshFiles, problems);
                String digest = text != null ? MeshCache.digest(text) : null;
                MeshData data = text != null ? meshData(text, digest, meshField(mesh, path),
                        limits.maxTriangles() - triangles, memory, problems) : null;
                if (data == null) {
                    shape = null;
                } else {
                    triangles += data.triangleCount();
                    MeshCache.Placement placement = new MeshCache.Placement(digest,
                            vec(or(mesh.position(), SceneDefaults.ORIGIN)), or(mesh.scale(), SceneDefaults.MESH_SCALE),
                            vec(or(mesh.rotation(), SceneDefaults.ORIGIN)));
                    shape = meshes.built(placement);
                    if (shape == null) {
                        TriangleMesh built = problems.attempt(path, () -> new TriangleMesh(data,
                                placement.position(), placement.scale(), placement.rotation(), memory));
                        if (built != null) {
                            meshes.keepBuilt(placement, built);
                        }
                        shape = built;
                    }
                }
            } else {
                shape = problems.attempt(path, () -> shape(o));
            }
            Material material = problems.attempt(path + ".material", () -> material(o.material()));
            if (shape != null && material != null) {
                objects.add(new SceneObject(shape, material));
            }
        }

        List<PointLight> lights = new ArrayList<>();
        if (dto.lights() == null) {
            lights.add(new PointLight(vec(SceneDefaults.LIGHT_POSITION), color(SceneDefaults.LIGHT_COLOR),
                    SceneDefaults.LIGHT_INTENSITY, false));
        } else {
            problems.atMost("lights", dto.lights().size(), limits.maxLights(), "lights");
            for (int i = 0; i < dto.lights().size() && i < limits.maxLights(); i++) {
                LightDto.Point l = (LightDto.Point) dto.lights().get(i);
                lights.add(new PointLight(vec(or(l.position(), SceneDefaults.LIGHT_POSITION)),
                        color(or(l.color(), SceneDefaults.LIGHT_COLOR)),
                        or(l.intensity(), SceneDefaults.LIGHT_INTENSITY), Boolean.TRUE.equals(l.falloff())));
            }
        }

        CameraDto c = dto.camera() != null ? dto.camera() : new CameraDto(null, null, null, null);
        Camera camera = problems.attempt("camera", () -> camera(c));

        problems.throwIfAny();
        Scene scene = new Scene(camera, objects, lights, color(or(dto.background(), SceneDefaults.BACKGROUND)),
                or(dto.ambient(), SceneDefaults.AMBIENT));
        RenderSettings settings = new RenderSettings(width, height, sampler, maxDepth, threads,
                or(render.seed(), SceneDefaults.SEED), RenderSettings.DEFAULT_MIN_PATH_WEIGHT, adaptive);
        return new CompiledScene(scene, settings, or(image.format(), SceneDefaults.FORMAT),
                or(image.quality(), SceneDefaults.JPEG_QUALITY), SceneNames.toFileStem(dto.name()));
    }

    private static Camera camera(CameraDto c) {
        Vec3 position = vec(or(c.position(), SceneDefaults.CAMERA_POSITION));
        Vec3 lookAt = vec(or(c.lookAt(), SceneDefaults.CAMERA_LOOK_AT));
        Vec3 up = vec(or(c.up(), SceneDefaults.CAMERA_UP));
        if (position.equals(lookAt)) {
            throw new FieldException("camera.lookAt", "must differ from camera.position");
        }
        Vec3 view = lookAt.minus(position);
        if (up.cross(view.normalized()).length() <= 1e-9 * up.length()) {
            throw new FieldException("camera.up", "is parallel to the view direction (lookAt - position); "
                    + "the camera's roll is undefined");
        }
        return new Camera(position, lookAt, up, or(c.fov(), SceneDefaults.CAMERA_FOV_DEGREES));
    }

    /** The mesh's OBJ text, inline or from its file; null (and a problem) if there is none. */
    private static String meshText(ObjectDto.Mesh mesh, String path, MeshFiles files, Problems problems) {
        if ((mesh.obj() == null) == (mesh.file() == null)) {
            problems.add(path, mesh.obj() == null ? "a mesh needs its OBJ text in \"obj\" or a \"file\" name"
                    : "give the mesh either \"obj\" or \"file\", not both");
            return null;
        }
        return mesh.obj() != null ? mesh.obj() : problems.attempt(path + ".file", () -> files.read(mesh.file()));
    }

    /** The field that holds the mesh's OBJ: its {@code obj} or its {@code file}. */
    private static String meshField(ObjectDto.Mesh mesh, String path) {
        return path + (mesh.obj() != null ? ".obj" : ".file");
    }

    /**
     * The OBJ data of a mesh's text (read before, or parsed now and kept); null (and a problem) if it
     * does not parse, or it has more than {@code triangleBudget} triangles (the reader stops there,
     * so a text of millions of triangles costs no more than the budget's worth).
     */
    private MeshData meshData(String text, String digest, String field, int triangleBudget, MemoryGate memory,
                              Problems problems) {
        MeshData data = meshes.parsed(digest);
        if (data == null) {
            try {
                data = ObjReader.parse(text, Math.max(0, triangleBudget), memory);
            } catch (TooManyTrianglesException e) {
                problems.add(field, "has more than " + triangleBudget + " triangles (passed at OBJ line " + e.line()
                        + "); this server's limit is " + triangleBudget + " more (all meshes together, "
                        + "studio.limits.max-triangles)");
                return null;
            } catch (IllegalArgumentException e) {
                problems.add(field, "is not a usable OBJ mesh: " + e.getMessage());
                return null;
            }
            meshes.keepParsed(digest, data);
        }
        if (data.triangleCount() > triangleBudget) {
            problems.add(field, "has " + data.triangleCount() + " triangles; this server's limit is "
                    + (triangleBudget < 0 ? 0 : triangleBudget) + " more (all meshes together, "
                    + "studio.limits.max-triangles)");
            return null;
        }
        return data;
    }

    private static Shape shape(ObjectDto o) {
        if (o instanceof ObjectDto.Sphere s) {
            return new Sphere(vec(or(s.center(), SceneDefaults.SPHERE_CENTER)), or(s.radius(), SceneDefaults.SPHERE_RADIUS));
        }
        if (o instanceof ObjectDto.Box b) {
            return new Box(vec(or(b.center(), SceneDefaults.BOX_CENTER)), vec(or(b.size(), SceneDefaults.BOX_SIZE)),
                    vec(or(b.rotation(), SceneDefaults.ORIGIN)));
        }
        if (o instanceof ObjectDto.Mesh) {
            throw new IllegalStateException("meshes are mapped by meshData");
        }
        ObjectDto.Plane p = (ObjectDto.Plane) o;
        return new Plane(vec(or(p.point(), SceneDefaults.ORIGIN)), vec(or(p.normal(), SceneDefaults.PLANE_NORMAL)));
    }

    /** The engine material for a DTO; a missing material is default chalk. (The peer benchmark uses it too.) */
    public static Material material(MaterialDto m) {
        if (m == null) {
            return MaterialDefaults.of(MaterialKind.CHALK, null);
        }
        Rgb color = m.color() != null ? color(m.color()) : null;
        if (m instanceof MaterialDto.Flat) {
            return MaterialDefaults.of(MaterialKind.FLAT, color);
        }
        if (m instanceof MaterialDto.Chalk c) {
            return MaterialDefaults.of(MaterialKind.CHALK, color, c.diffuse(), null, null, null, null);
        }
        if (m instanceof MaterialDto.Plastic p) {
            return MaterialDefaults.of(MaterialKind.PLASTIC, color, p.diffuse(), p.specular(), p.shininess(), null, null);
        }
        if (m instanceof MaterialDto.Metal x) {
            return MaterialDefaults.of(MaterialKind.METAL, color, x.diffuse(), x.specular(), x.shininess(),
                    x.reflectivity(), null);
        }
        if (m instanceof MaterialDto.Mirror x) {
            return MaterialDefaults.of(MaterialKind.MIRROR, color, null, null, null, x.reflectivity(), null);
        }
        MaterialDto.Glass g = (MaterialDto.Glass) m;
        return MaterialDefaults.of(MaterialKind.GLASS, color, null, g.specular(), g.shininess(), null, g.ior());
    }

    /** "#rrggbb" (already validated) in linear light. */
    public static Rgb color(String hex) {
        int rgb = Integer.parseInt(hex.substring(1), 16);
        return Rgb.fromSrgb8(rgb >> 16 & 0xff, rgb >> 8 & 0xff, rgb & 0xff);
    }

    private static Vec3 vec(List<Double> v) {
        return new Vec3(v.get(0), v.get(1), v.get(2));
    }

    private static <T> T or(T value, T fallback) {
        return value != null ? value : fallback;
    }

    /** A problem found while mapping, already naming its field. */
    private static final class FieldException extends RuntimeException {
        final String field;

        FieldException(String field, String message) {
            super(message);
            this.field = field;
        }
    }

    /** Collects problems so that one response lists them all. */
    private static final class Problems {
        private final List<FieldProblem> list = new ArrayList<>();

        void add(String field, String message) {
            list.add(new FieldProblem(field, message));
        }

        void atMost(String field, int value, int max) {
            if (value > max) {
                list.add(new FieldProblem(field, "must be at most " + max + " (this server's limit), not " + value));
            }
        }

        void atMost(String field, int count, int max, String what) {
            if (count > max) {
                list.add(new FieldProblem(field, "has " + count + " " + what + "; this server's limit is " + max));
            }
        }

        /** Runs an engine constructor; its IllegalArgumentException becomes a problem at {@code field}. */
        <T> T attempt(String field, java.util.function.Supplier<T> build) {
            try {
                return build.get();
            } catch (FieldException e) {
                list.add(new FieldProblem(e.field, e.getMessage()));
            } catch (IllegalArgumentException e) {
                list.add(new FieldProblem(field, e.getMessage()));
            }
            return null;
        }

        void throwIfAny() {
            if (!list.isEmpty()) {
                throw new InvalidSceneException(list);
            }
        }
    }
}
