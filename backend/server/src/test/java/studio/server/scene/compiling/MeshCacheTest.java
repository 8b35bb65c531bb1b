package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Locale;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.geometry.Shape;
import studio.engine.geometry.TriangleMesh;
import studio.engine.mesh.MeshShapes;
import studio.engine.mesh.ObjWriter;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;
import studio.server.system.MemoryBudget;

/** Meshes reused by content: a scene sent again with other things moved keeps its built mesh. */
class MeshCacheTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());
    /** A 3,840-triangle torus knot as inline OBJ text, escaped for a JSON string. */
    private static final String KNOT = obj(MeshShapes.torusKnot(2, 3, 120, 16));

    private static String obj(studio.engine.mesh.MeshData mesh) {
        StringBuilder text = new StringBuilder();
        try {
            ObjWriter.write(mesh, text);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return text.toString().replace("\n", "\\n");
    }

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static String scene(String obj, double meshX, double sphereX) {
        return """
                {"image": {"width": 8, "height": 6}, "render": {"samples": 1},
                 "objects": [{"type": "mesh", "obj": "%s", "position": [%s, 0, 0]},
                             {"type": "sphere", "center": [%s, 0, 0]}]}
                """.formatted(obj, meshX, sphereX);
    }

    private static Shape meshOf(SceneMapper mapper, String json) {
        return mapper.map(READER.read(json.getBytes(java.nio.charset.StandardCharsets.UTF_8)), 1).scene().shape(0);
    }

    @Test
    void movingAnotherObjectKeepsTheBuiltMeshMovingTheMeshMovesItsTree() {
        MemoryBudget memory = new MemoryBudget(1L << 30);
        MeshCache cache = new MeshCache(1_000_000, memory);
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, cache);
        Shape first = meshOf(mapper, scene(KNOT, 0, 3));
        assertThat(meshOf(mapper, scene(KNOT, 0, 4))).isSameAs(first);
        TriangleMesh moved = (TriangleMesh) meshOf(mapper, scene(KNOT, 1, 4));
        assertThat(moved).isNotSameAs(first);
        assertThat(((TriangleMesh) first).buildNanos()).isPositive();
        assertThat(moved.buildNanos()).as("the tree moved with the mesh, not built again").isZero();
        TriangleMesh builtThere = (TriangleMesh) meshOf(new SceneMapper(SceneLimits.DEFAULTS), scene(KNOT, 1, 4));
        assertThat(moved.positions()).isEqualTo(builtThere.positions());
        assertThat(moved.indices()).isEqualTo(builtThere.indices());
        assertThat(moved.bounds()).isEqualTo(builtThere.bounds());
        assertThat(meshOf(mapper, scene(KNOT, 1, 5))).isSameAs(moved);
        // parsed once, built twice: three entries of 3,840 triangles, each holding its memory
        assertThat(cache.triangles()).isEqualTo(3 * 3_840);
        assertThat(memory.reserved()).isEqualTo(3 * 3_840 * MeshCache.BYTES_PER_TRIANGLE);
    }

    @Test
    void withoutACacheEveryMappingBuildsItsOwnMesh() {
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS);
        assertThat(meshOf(mapper, scene(KNOT, 0, 4))).isNotSameAs(meshOf(mapper, scene(KNOT, 0, 4)));
    }

    @Test
    void aCacheThatKeepsNothingHashesNoText() {
        assertThat(MeshCache.none().keyOf(KNOT)).isNull();
        MeshCache cache = new MeshCache(1_000_000, MemoryBudget.unlimited());
        assertThat(cache.keyOf(KNOT)).hasSize(64).isEqualTo(cache.keyOf(KNOT))
                .isNotEqualTo(cache.keyOf(KNOT.replaceFirst("v ", "v  ")));
    }

    @Test
    void theOldestEntriesGoFirstAndGiveTheirMemoryBack() {
        MemoryBudget memory = new MemoryBudget(1L << 30);
        MeshCache cache = new MeshCache(2 * 3_840, memory);
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, cache);
        Shape first = meshOf(mapper, scene(KNOT, 0, 3));
        meshOf(mapper, scene(KNOT, 1, 3));
        meshOf(mapper, scene(KNOT, 2, 3));
        assertThat(cache.triangles()).isLessThanOrEqualTo(2 * 3_840);
        assertThat(memory.reserved()).isEqualTo(cache.triangles() * MeshCache.BYTES_PER_TRIANGLE);
        assertThat(meshOf(mapper, scene(KNOT, 0, 3))).as("evicted, so built again").isNotSameAs(first);
    }

    @Test
    void aMeshTheMemoryBudgetCannotCoverIsNotKept() {
        MemoryBudget memory = new MemoryBudget(3_840 * MeshCache.BYTES_PER_TRIANGLE - 1);
        MeshCache cache = new MeshCache(1_000_000, memory);
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, cache);
        Shape first = meshOf(mapper, scene(KNOT, 0, 3));
        assertThat(meshOf(mapper, scene(KNOT, 0, 4))).isNotSameAs(first);
        assertThat(cache.triangles()).isZero();
        assertThat(memory.reserved()).isZero();
    }

    @Test
    void differentTextsNeverShareAnEntry() {
        MeshCache cache = new MeshCache(1_000_000, MemoryBudget.unlimited());
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS, cache);
        String other = obj(MeshShapes.torusKnot(3, 2, 120, 16));
        assertThat(meshOf(mapper, scene(other, 0, 3))).isNotSameAs(meshOf(mapper, scene(KNOT, 0, 3)));
    }
}
