package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.Locale;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.geometry.TriangleMesh;
import studio.engine.memory.MemoryGate;
import studio.engine.mesh.MeshShapes;
import studio.engine.mesh.ObjWriter;
import studio.server.scene.format.SceneLimits;
import studio.server.scene.reading.SceneReader;

/** A scene's meshes get light buffers when its render has enough camera samples, asked of its memory. */
class LightBufferMappingTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader READER = new SceneReader(VALIDATION.getValidator());

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    /** A 3,840-triangle knot lit by two lights, at the given image size and samples. */
    private static CompiledScene map(int width, int height, int samples, MemoryGate memory)
            throws Exception {
        StringBuilder obj = new StringBuilder();
        ObjWriter.write(MeshShapes.torusKnot(2, 3, 120, 16), obj);
        String json = """
                {"image": {"width": %d, "height": %d}, "render": {"samples": %d},
                 "lights": [{"type": "point", "position": [-3, 6, 4]}, {"type": "point", "position": [5, 4, -2]}],
                 "objects": [{"type": "mesh", "obj": "%s", "position": [0, 1.5, 0]}]}
                """.formatted(width, height, samples, obj.toString().replace("\n", "\\n"));
        SceneMapper mapper = new SceneMapper(SceneLimits.DEFAULTS);
        return mapper.map(READER.read(json.getBytes(StandardCharsets.UTF_8)), 1, MeshFiles.none(), memory);
    }

    @Test
    void aLongRenderGetsABufferPerLightAndAShortOneNone() throws Exception {
        long[] lit = {0}, plain = {0};
        assertThat(((TriangleMesh) map(160, 96, 2, bytes -> lit[0] += bytes).scene().shape(0)).lightBufferCount())
                .isEqualTo(2);
        assertThat(((TriangleMesh) map(40, 30, 4, bytes -> plain[0] += bytes).scene().shape(0)).lightBufferCount())
                .isZero();
        assertThat(lit[0]).as("with the buffers' memory").isGreaterThan(plain[0] + 2 * 3_840 * 8);
    }

    @Test
    void aMeshWhoseBuffersTheMemoryCannotSpareRendersWithout() throws Exception {
        MemoryGate busy = new MemoryGate() {
            @Override
            public void reserve(long bytes) {
                // the mesh itself is granted
            }

            @Override
            public boolean tryReserve(long bytes) {
                return false; // nothing to spare for a speed-up
            }
        };
        assertThat(((TriangleMesh) map(160, 96, 2, busy).scene().shape(0)).lightBufferCount()).isZero();
    }
}
