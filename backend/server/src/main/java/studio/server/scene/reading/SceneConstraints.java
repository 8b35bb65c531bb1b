package studio.server.scene.reading;

import static java.util.Map.entry;

import java.util.List;
import java.util.Map;

import studio.server.scene.format.CameraDto;
import studio.server.scene.format.ImageDto;
import studio.server.scene.format.LightDto;
import studio.server.scene.format.MaterialDto;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.RenderDto;
import studio.server.scene.format.SceneDto;
import studio.server.scene.format.TextureDto;

/**
 * Generated from the scene records' annotations by SceneConstraintsTest, which fails when this
 * file differs from what it would write; regenerate it rather than edit it:
 * {@code mvn -f backend/pom.xml -pl engine,server test -Dtest=SceneConstraintsTest
 * -Dsurefire.failIfNoSpecifiedTests=false -Dscene-constraints.write=true}.
 *
 * <p>The constraints {@link FastPathBinder} checks, as data: per record field ("Type.field", and
 * "Type.field[]" for a list's elements) the rules its annotations state, and per polymorphic
 * type its type property and kinds; and each record's constructor, called directly.
 */
final class SceneConstraints {

    private SceneConstraints() {
    }

    /** A polymorphic type: the JSON property that names the kind, and each kind's record. */
    record Subtypes(String property, Map<String, Class<?>> byName) {
    }

    static final Map<String, List<FieldRule>> RULES = Map.ofEntries(
            entry("SceneDto.version", List.of(new FieldRule.Min(1L), new FieldRule.Max(1L))),
            entry("SceneDto.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("SceneDto.image", List.of()),
            entry("ImageDto.width", List.of(new FieldRule.Positive())),
            entry("ImageDto.height", List.of(new FieldRule.Positive())),
            entry("ImageDto.format", List.of(new FieldRule.Pattern("jpg|png"))),
            entry("ImageDto.quality", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("SceneDto.camera", List.of()),
            entry("CameraDto.position", List.of(new FieldRule.Vector())),
            entry("CameraDto.position[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("CameraDto.lookAt", List.of(new FieldRule.Vector())),
            entry("CameraDto.lookAt[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("CameraDto.up", List.of(new FieldRule.Vector(), new FieldRule.NonZeroVector())),
            entry("CameraDto.up[]", List.of(new FieldRule.NotNull(), new FieldRule.Finite())),
            entry("CameraDto.fov", List.of(
                    new FieldRule.DecimalMin("0", false),
                    new FieldRule.DecimalMax("180", false),
                    new FieldRule.Finite())),
            entry("SceneDto.background", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("SceneDto.ambient", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("SceneDto.render", List.of()),
            entry("RenderDto.sampler", List.of(new FieldRule.Pattern("regular|random|jittered|multijittered|sobol"))),
            entry("RenderDto.samples", List.of(new FieldRule.Positive())),
            entry("RenderDto.maxDepth", List.of(new FieldRule.PositiveOrZero())),
            entry("RenderDto.seed", List.of()),
            entry("RenderDto.adaptive", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("SceneDto.lights", List.of()),
            entry("SceneDto.lights[]", List.of(new FieldRule.NotNull())),
            entry("LightDto.Point.position", List.of(new FieldRule.Vector())),
            entry("LightDto.Point.position[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("LightDto.Point.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("LightDto.Point.intensity", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1e6", true),
                    new FieldRule.Finite())),
            entry("LightDto.Point.falloff", List.of()),
            entry("LightDto.Point.radius", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1e6", true),
                    new FieldRule.Finite())),
            entry("LightDto.Point.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("LightDto.Area.position", List.of(new FieldRule.Vector())),
            entry("LightDto.Area.position[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("LightDto.Area.size", List.of(new FieldRule.Pair())),
            entry("LightDto.Area.size[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.Positive(),
                    new FieldRule.DecimalMax("1e6", true),
                    new FieldRule.Finite())),
            entry("LightDto.Area.lookAt", List.of(new FieldRule.Vector())),
            entry("LightDto.Area.lookAt[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("LightDto.Area.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("LightDto.Area.intensity", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1e6", true),
                    new FieldRule.Finite())),
            entry("LightDto.Area.falloff", List.of()),
            entry("LightDto.Area.twoSided", List.of()),
            entry("LightDto.Area.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("SceneDto.objects", List.of(new FieldRule.NotNull())),
            entry("SceneDto.objects[]", List.of(new FieldRule.NotNull())),
            entry("ObjectDto.Sphere.center", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Sphere.center[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("ObjectDto.Sphere.radius", List.of(new FieldRule.Positive(), new FieldRule.Finite())),
            entry("ObjectDto.Sphere.material", List.of()),
            entry("MaterialDto.Flat.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Flat.texture", List.of()),
            entry("TextureDto.Checker.colors", List.of()),
            entry("TextureDto.Checker.colors[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("TextureDto.Checker.size", List.of(new FieldRule.Positive(), new FieldRule.Finite())),
            entry("TextureDto.Image.asset", List.of(new FieldRule.Pattern("sha256-[0-9a-f]{64}"))),
            entry("TextureDto.Image.file", List.of(
                    new FieldRule.Pattern("(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.(png|jpg|jpeg)"))),
            entry("TextureDto.Image.scale", List.of()),
            entry("TextureDto.Image.scale[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.Positive(),
                    new FieldRule.Finite())),
            entry("MaterialDto.Chalk.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Chalk.diffuse", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Chalk.texture", List.of()),
            entry("MaterialDto.Plastic.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Plastic.diffuse", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Plastic.specular", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Plastic.shininess", List.of(
                    new FieldRule.DecimalMin("1", true),
                    new FieldRule.DecimalMax("10000", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Plastic.texture", List.of()),
            entry("MaterialDto.Metal.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Metal.diffuse", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Metal.specular", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Metal.shininess", List.of(
                    new FieldRule.DecimalMin("1", true),
                    new FieldRule.DecimalMax("10000", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Metal.reflectivity", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Metal.texture", List.of()),
            entry("MaterialDto.Mirror.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Mirror.reflectivity", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Mirror.texture", List.of()),
            entry("MaterialDto.Glass.color", List.of(new FieldRule.Pattern("#[0-9a-fA-F]{6}"))),
            entry("MaterialDto.Glass.ior", List.of(
                    new FieldRule.DecimalMin("1", true),
                    new FieldRule.DecimalMax("4", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Glass.specular", List.of(
                    new FieldRule.PositiveOrZero(),
                    new FieldRule.DecimalMax("1", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Glass.shininess", List.of(
                    new FieldRule.DecimalMin("1", true),
                    new FieldRule.DecimalMax("10000", true),
                    new FieldRule.Finite())),
            entry("MaterialDto.Glass.texture", List.of()),
            entry("ObjectDto.Sphere.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("ObjectDto.Box.center", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Box.center[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("ObjectDto.Box.size", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Box.size[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.Positive(),
                    new FieldRule.Finite())),
            entry("ObjectDto.Box.rotation", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Box.rotation[]", List.of(new FieldRule.NotNull(), new FieldRule.Finite())),
            entry("ObjectDto.Box.material", List.of()),
            entry("ObjectDto.Box.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("ObjectDto.Plane.point", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Plane.point[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("ObjectDto.Plane.normal", List.of(new FieldRule.Vector(), new FieldRule.NonZeroVector())),
            entry("ObjectDto.Plane.normal[]", List.of(new FieldRule.NotNull(), new FieldRule.Finite())),
            entry("ObjectDto.Plane.material", List.of()),
            entry("ObjectDto.Plane.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("ObjectDto.Mesh.obj", List.of()),
            entry("ObjectDto.Mesh.file", List.of(
                    new FieldRule.Pattern("(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.obj"))),
            entry("ObjectDto.Mesh.asset", List.of(new FieldRule.Pattern("sha256-[0-9a-f]{64}"))),
            entry("ObjectDto.Mesh.position", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Mesh.position[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("ObjectDto.Mesh.scale", List.of(new FieldRule.Positive(), new FieldRule.Finite())),
            entry("ObjectDto.Mesh.rotation", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Mesh.rotation[]", List.of(new FieldRule.NotNull(), new FieldRule.Finite())),
            entry("ObjectDto.Mesh.material", List.of()),
            entry("ObjectDto.Mesh.name", List.of(new FieldRule.CodePointLength(0, 200))),
            entry("ObjectDto.Gltf.file", List.of(
                    new FieldRule.Pattern("(?!.*\\.\\.)(?!.*/\\.)(?!.*//)[A-Za-z0-9_-][A-Za-z0-9._/-]*\\.(glb|gltf)"))),
            entry("ObjectDto.Gltf.asset", List.of(new FieldRule.Pattern("sha256-[0-9a-f]{64}"))),
            entry("ObjectDto.Gltf.position", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Gltf.position[]", List.of(
                    new FieldRule.NotNull(),
                    new FieldRule.DecimalMin("-1e12", true),
                    new FieldRule.DecimalMax("1e12", true),
                    new FieldRule.Finite())),
            entry("ObjectDto.Gltf.scale", List.of(new FieldRule.Positive(), new FieldRule.Finite())),
            entry("ObjectDto.Gltf.rotation", List.of(new FieldRule.Vector())),
            entry("ObjectDto.Gltf.rotation[]", List.of(new FieldRule.NotNull(), new FieldRule.Finite())),
            entry("ObjectDto.Gltf.name", List.of(new FieldRule.CodePointLength(0, 200))));

    static final Map<Class<?>, Subtypes> SUBTYPES = Map.ofEntries(
            entry(LightDto.class, new Subtypes("type", Map.ofEntries(
                    entry("point", LightDto.Point.class),
                    entry("area", LightDto.Area.class)))),
            entry(ObjectDto.class, new Subtypes("type", Map.ofEntries(
                    entry("sphere", ObjectDto.Sphere.class),
                    entry("box", ObjectDto.Box.class),
                    entry("plane", ObjectDto.Plane.class),
                    entry("mesh", ObjectDto.Mesh.class),
                    entry("gltf", ObjectDto.Gltf.class)))),
            entry(MaterialDto.class, new Subtypes("type", Map.ofEntries(
                    entry("flat", MaterialDto.Flat.class),
                    entry("chalk", MaterialDto.Chalk.class),
                    entry("plastic", MaterialDto.Plastic.class),
                    entry("metal", MaterialDto.Metal.class),
                    entry("mirror", MaterialDto.Mirror.class),
                    entry("glass", MaterialDto.Glass.class)))),
            entry(TextureDto.class, new Subtypes("type", Map.ofEntries(
                    entry("checker", TextureDto.Checker.class),
                    entry("image", TextureDto.Image.class)))));

    /** A record of {@code type} from its components' values, in declaration order. */
    @SuppressWarnings("unchecked")
    static Object make(Class<?> type, Object[] v) {
        if (type == ImageDto.class) {
            return new ImageDto((Integer) v[0], (Integer) v[1], (String) v[2], (Double) v[3]);
        }
        if (type == CameraDto.class) {
            return new CameraDto((List<Double>) v[0], (List<Double>) v[1], (List<Double>) v[2], (Double) v[3]);
        }
        if (type == RenderDto.class) {
            return new RenderDto((String) v[0], (Integer) v[1], (Integer) v[2], (Long) v[3], (Double) v[4]);
        }
        if (type == LightDto.Point.class) {
            return new LightDto.Point(
                    (List<Double>) v[0],
                    (String) v[1],
                    (Double) v[2],
                    (Boolean) v[3],
                    (Double) v[4],
                    (String) v[5]);
        }
        if (type == LightDto.Area.class) {
            return new LightDto.Area(
                    (List<Double>) v[0],
                    (List<Double>) v[1],
                    (List<Double>) v[2],
                    (String) v[3],
                    (Double) v[4],
                    (Boolean) v[5],
                    (Boolean) v[6],
                    (String) v[7]);
        }
        if (type == TextureDto.Checker.class) {
            return new TextureDto.Checker((List<String>) v[0], (Double) v[1]);
        }
        if (type == TextureDto.Image.class) {
            return new TextureDto.Image((String) v[0], (String) v[1], (List<Double>) v[2]);
        }
        if (type == MaterialDto.Flat.class) {
            return new MaterialDto.Flat((String) v[0], (TextureDto) v[1]);
        }
        if (type == MaterialDto.Chalk.class) {
            return new MaterialDto.Chalk((String) v[0], (Double) v[1], (TextureDto) v[2]);
        }
        if (type == MaterialDto.Plastic.class) {
            return new MaterialDto.Plastic(
                    (String) v[0],
                    (Double) v[1],
                    (Double) v[2],
                    (Double) v[3],
                    (TextureDto) v[4]);
        }
        if (type == MaterialDto.Metal.class) {
            return new MaterialDto.Metal(
                    (String) v[0],
                    (Double) v[1],
                    (Double) v[2],
                    (Double) v[3],
                    (Double) v[4],
                    (TextureDto) v[5]);
        }
        if (type == MaterialDto.Mirror.class) {
            return new MaterialDto.Mirror((String) v[0], (Double) v[1], (TextureDto) v[2]);
        }
        if (type == MaterialDto.Glass.class) {
            return new MaterialDto.Glass((String) v[0], (Double) v[1], (Double) v[2], (Double) v[3], (TextureDto) v[4]);
        }
        if (type == ObjectDto.Sphere.class) {
            return new ObjectDto.Sphere((List<Double>) v[0], (Double) v[1], (MaterialDto) v[2], (String) v[3]);
        }
        if (type == ObjectDto.Box.class) {
            return new ObjectDto.Box(
                    (List<Double>) v[0],
                    (List<Double>) v[1],
                    (List<Double>) v[2],
                    (MaterialDto) v[3],
                    (String) v[4]);
        }
        if (type == ObjectDto.Plane.class) {
            return new ObjectDto.Plane((List<Double>) v[0], (List<Double>) v[1], (MaterialDto) v[2], (String) v[3]);
        }
        if (type == ObjectDto.Mesh.class) {
            return new ObjectDto.Mesh(
                    (String) v[0],
                    (String) v[1],
                    (String) v[2],
                    (List<Double>) v[3],
                    (Double) v[4],
                    (List<Double>) v[5],
                    (MaterialDto) v[6],
                    (String) v[7]);
        }
        if (type == ObjectDto.Gltf.class) {
            return new ObjectDto.Gltf(
                    (String) v[0],
                    (String) v[1],
                    (List<Double>) v[2],
                    (Double) v[3],
                    (List<Double>) v[4],
                    (String) v[5]);
        }
        if (type == SceneDto.class) {
            return new SceneDto(
                    (Integer) v[0],
                    (String) v[1],
                    (ImageDto) v[2],
                    (CameraDto) v[3],
                    (String) v[4],
                    (Double) v[5],
                    (RenderDto) v[6],
                    (List<LightDto>) v[7],
                    (List<ObjectDto>) v[8]);
        }
        throw new IllegalArgumentException("no record the fast path reads: " + type.getName());
    }
}
