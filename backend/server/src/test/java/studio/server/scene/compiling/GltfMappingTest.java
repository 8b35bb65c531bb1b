package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;
import static org.assertj.core.api.Assertions.within;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tools.jackson.databind.node.ObjectNode;

import studio.engine.geometry.TriangleMesh;
import studio.engine.material.MaterialKind;
import studio.engine.memory.MemoryGate;
import studio.engine.texture.ImageTexture;
import studio.server.scene.gltf.TestGltf;
import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.scene.reading.SceneValidationTest;
import studio.server.system.MemoryBudget;

/** The {@code gltf} object: a model's parts placed as scene objects by its node transforms, then by the object's placement. */
class GltfMappingTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());
    private static final String ID = "sha256-" + "ab".repeat(32);

    @TempDir
    Path dir;

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    /** The assets of a server that holds {@code gltf} as {@link #ID}. */
    private static MeshAssets holding(byte[] gltf) {
        return new MeshAssets() {
            @Override
            public byte[] obj(String id) {
                throw new IllegalArgumentException("not a mesh");
            }

            @Override
            public byte[] gltf(String id) {
                return id.equals(ID) ? gltf : null;
            }
        };
    }

    private static CompiledScene map(String objects, SceneMapper mapper, MeshFiles files) {
        String json = "{'image':{'width':8,'height':6},'render':{'samples':1,'maxDepth':1},'objects':[" + objects + "]}";
        return mapper.map(READER.read(SceneValidationTest.json(json)), 1, files, MemoryGate.UNLIMITED);
    }

    private static List<FieldProblem> problems(String objects, SceneMapper mapper) {
        InvalidSceneException e = catchThrowableOfType(InvalidSceneException.class,
                () -> map(objects, mapper, MeshFiles.none()));
        assertThat(e).as("expected the scene to be refused").isNotNull();
        return e.problems();
    }

    private static void assertVertex(double[] p, int v, double x, double y, double z) {
        assertThat(new double[] {p[3 * v], p[3 * v + 1], p[3 * v + 2]}).containsExactly(new double[] {x, y, z},
                within(1e-12));
    }

    /** The triangle under a parent moved by (1, 0, 0) and a child scaled by 2: (1,0,0), (3,0,0), (1,2,0). */
    static ObjectNode nestedTriangle() {
        return TestGltf.triangle("[{\"translation\": [1, 0, 0], \"children\": [1]}, {\"scale\": [2, 2, 2], \"mesh\": 0}]");
    }

    @Test
    void placesTheModelByItsNodesThenByTheObjectsScaleRotationAndPosition() {
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(),
                holding(TestGltf.glb(nestedTriangle(), TestGltf.triangleBuffer())));
        CompiledScene compiled = map("{'type':'gltf','asset':'" + ID + "','position':[0,0,-5],'scale':0.5,"
                + "'rotation':[0,0,90]}", mapper, MeshFiles.none());

        assertThat(compiled.scene().objectCount()).isEqualTo(1);
        TriangleMesh mesh = (TriangleMesh) compiled.scene().shape(0);
        // halved: (0.5,0,0), (1.5,0,0), (0.5,1,0); turned 90 degrees about z ((x, y) -> (-y, x)); moved by (0,0,-5)
        double[] p = mesh.positions();
        int[] triangle = mesh.indices();
        assertVertex(p, triangle[0], 0, 0.5, -5);
        assertVertex(p, triangle[1], 0, 1.5, -5);
        assertVertex(p, triangle[2], -1, 0.5, -5);
        assertThat(compiled.scene().material(0).kind()).isEqualTo(MaterialKind.PLASTIC);
    }

    @Test
    void readsAModelFileBesideTheScene() throws IOException {
        Files.write(dir.resolve("box.gltf"), TestGltf.khronos("BoxTextured/BoxTextured.gltf"));
        CompiledScene compiled = map("{'type':'gltf','file':'box.gltf'}", new SceneMapper(SceneLimits.DEFAULTS),
                MeshFiles.in(dir));
        assertThat(((TriangleMesh) compiled.scene().shape(0)).triangleCount()).isEqualTo(12);
    }

    @Test
    void drawsABaseColourTextureOnTheModelsUvs() throws IOException {
        Files.write(dir.resolve("box.gltf"), TestGltf.khronos("BoxTextured/BoxTextured.gltf"));
        CompiledScene compiled = map("{'type':'gltf','file':'box.gltf'}", new SceneMapper(SceneLimits.DEFAULTS),
                MeshFiles.in(dir));
        assertThat(((TriangleMesh) compiled.scene().shape(0)).hasUvs()).isTrue();
        assertThat(compiled.scene().material(0).texture()).isInstanceOf(ImageTexture.class);
        assertThat(((ImageTexture) compiled.scene().material(0).texture()).image().width()).isGreaterThan(1);
    }

    @Test
    void keepsAModelForTheNextCompile() {
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, new MeshCache(10_000, MemoryBudget.unlimited()),
                holding(TestGltf.bytes(nestedTriangle())));
        TriangleMesh first = (TriangleMesh) map("{'type':'gltf','asset':'" + ID + "'}", mapper, MeshFiles.none())
                .scene().shape(0);
        TriangleMesh moved = (TriangleMesh) map("{'type':'gltf','asset':'" + ID + "','position':[1,0,0]}", mapper,
                MeshFiles.none()).scene().shape(0);
        assertThat(moved.positions()[3 * moved.indices()[0]]).isEqualTo(first.positions()[3 * first.indices()[0]] + 1);
    }

    @Test
    void namesEachBadForm() {
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(),
                holding(TestGltf.bytes(nestedTriangle())));
        assertThat(problems("{'type':'gltf','asset':'sha256-" + "cd".repeat(32) + "'}", mapper).get(0))
                .isEqualTo(new FieldProblem("objects[0].asset", "this server has no asset sha256-" + "cd".repeat(32)
                        + "; upload it (POST /api/assets) and send the scene again"));
        assertThat(problems("{'type':'gltf'}", mapper).get(0))
                .isEqualTo(new FieldProblem("objects[0]", "a glTF model needs a \"file\" name or an \"asset\" id"));
        assertThat(problems("{'type':'gltf','asset':'" + ID + "','file':'a.glb'}", mapper).get(0).field())
                .isEqualTo("objects[0]");
        assertThat(problems("{'type':'gltf','file':'a.glb'}", mapper).get(0))
                .isEqualTo(new FieldProblem("objects[0].file", "glTF files cannot be read here; upload the model "
                        + "(POST /api/assets) and name it by its id in \"asset\""));
    }

    @Test
    void namesABrokenModelByItsField() {
        ObjectNode broken = nestedTriangle();
        ((ObjectNode) broken.get("accessors").get(1)).put("count", 6);
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(), holding(TestGltf.bytes(broken)));
        FieldProblem p = problems("{'type':'gltf','asset':'" + ID + "'}", mapper).get(0);
        assertThat(p.field()).isEqualTo("objects[0].asset");
        assertThat(p.message()).startsWith("is not a glTF 2.0 model that can be drawn: accessors[1]: its 6 elements");
    }

    @Test
    void aModelIsAnObjectForEachOfItsMaterialsAndEachCountsTowardsTheLimit() {
        ObjectNode gltf = nestedTriangle();
        gltf.withArray("materials").add(TestGltf.JSON.readTree("{\"pbrMetallicRoughness\": {\"metallicFactor\": 1}}"));
        ((ObjectNode) gltf.get("meshes").get(0)).withArray("primitives").add(TestGltf.JSON.readTree(
                "{\"attributes\": {\"POSITION\": 0}, \"indices\": 1, \"material\": 1}"));
        MeshAssets assets = holding(TestGltf.bytes(gltf));
        CompiledScene compiled = map("{'type':'gltf','asset':'" + ID + "'}",
                new SceneMapper(SceneLimits.DEFAULTS, MeshCache.none(), assets), MeshFiles.none());
        assertThat(compiled.scene().objectCount()).isEqualTo(2);
        assertThat(compiled.scene().material(0).kind()).isEqualTo(MaterialKind.PLASTIC);
        assertThat(compiled.scene().material(1).kind()).isEqualTo(MaterialKind.METAL);

        SceneLimits twoObjects = new SceneLimits(640, 480, 64, 4, 2, 3, 1000, 1 << 20);
        assertThat(problems("{'type':'sphere'},{'type':'gltf','asset':'" + ID + "'}",
                new SceneMapper(twoObjects, MeshCache.none(), assets))).containsExactly(new FieldProblem("objects[1]",
                "brings the scene to 3 objects (one for each of a model's materials); this server's limit is 2"));
    }

    @Test
    void countsAModelsTrianglesWithTheScenesMeshes() {
        SceneLimits oneTriangle = new SceneLimits(640, 480, 64, 4, 50, 3, 1, 1 << 20);
        SceneMapper mapper = new SceneMapper(oneTriangle, MeshCache.none(), holding(TestGltf.bytes(nestedTriangle())));
        List<FieldProblem> problems = problems("{'type':'gltf','asset':'" + ID + "'},{'type':'gltf','asset':'" + ID
                + "'}", mapper);
        assertThat(problems).containsExactly(new FieldProblem("objects[1].asset", "draws 1 triangles; this server's "
                + "limit is 0 more (all meshes together, studio.limits.max-triangles)"));
    }
}
