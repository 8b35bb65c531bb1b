package studio.server.scene.compiling;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import studio.engine.geometry.TriangleMesh;
import studio.engine.math.Vec3;
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
        Asked lit = new Asked(true), plain = new Asked(true), buffers = new Asked(true);
        TriangleMesh mesh = (TriangleMesh) map(40, 30, 4, plain).scene().shape(0);
        map(160, 96, 2, lit);
        mesh.withLightBuffers(List.of(new Vec3(-3, 6, 4), new Vec3(5, 4, -2)), buffers);
        assertThat(plain.spared).as("a short render: no buffers").isZero();
        assertThat(buffers.spared).as("a buffer per light").isGreaterThan(2 * 3_840 * 8);
        assertThat(lit.spared).as("a long render: the buffers of both lights").isEqualTo(buffers.spared);
    }

    @Test
    void aMeshWhoseBuffersTheMemoryCannotSpareRendersWithout() throws Exception {
        Asked busy = new Asked(false); // the mesh itself is granted, nothing to spare for a speed-up
        assertThat(map(160, 96, 2, busy).scene().shape(0)).isInstanceOf(TriangleMesh.class);
        assertThat(busy.refused).as("the buffers were asked for").isPositive();
        assertThat(busy.spared).isZero();
    }

    /** A gate that grants what it is asked to reserve and counts what it is asked to spare. */
    private static final class Asked implements MemoryGate {

        private final boolean spares;
        long spared;
        int refused;

        Asked(boolean spares) {
            this.spares = spares;
        }

        @Override
        public void reserve(long bytes) {
            // granted
        }

        @Override
        public boolean tryReserve(long bytes) {
            if (spares) {
                spared += bytes;
            } else {
                refused++;
            }
            return spares;
        }
    }
}
