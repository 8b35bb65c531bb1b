package studio.server.scene;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.function.IntFunction;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

/**
 * Long object lists are bound and validated in parallel; the result, and every problem with its
 * path and message, must be what reading them in one piece gives.
 */
class SceneReaderParallelTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader PARALLEL = new SceneReader(VALIDATION::getValidator, 16, false);
    private static final SceneReader IN_ONE_PIECE = new SceneReader(VALIDATION::getValidator, Integer.MAX_VALUE, false);
    private static final int N = 1500;

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static byte[] scene(IntFunction<String> object) {
        StringBuilder json = new StringBuilder("{\"name\": \"many\", \"camera\": {\"fov\": 40}, \"objects\": [");
        for (int i = 0; i < N; i++) {
            json.append(i > 0 ? ", " : "").append(object.apply(i));
        }
        return json.append("]}").toString().getBytes(StandardCharsets.UTF_8);
    }

    private static String sphere(int i) {
        return "{\"type\": \"sphere\", \"center\": [" + i + ", 0, 0], \"radius\": 0.5, "
                + "\"material\": {\"type\": \"plastic\", \"color\": \"#336699\"}}";
    }

    @Test
    void readsTheSameSceneBothWays() {
        byte[] json = scene(i -> i % 3 == 0 ? sphere(i) : i % 3 == 1
                ? "{\"type\": \"box\", \"center\": [0, " + i + ", 0], \"size\": [1, 2, 3], \"rotation\": [0, 45, 0]}"
                : "{\"type\": \"plane\", \"point\": [0, 0, " + i + "], \"normal\": [0, 1, 0]}");
        SceneDto parallel = PARALLEL.read(json);
        assertThat(parallel).isEqualTo(IN_ONE_PIECE.read(json));
        assertThat(parallel.objects()).hasSize(N);
        assertThat(parallel.objects().get(N - 2)).isInstanceOf(ObjectDto.Box.class);
    }

    @Test
    void reportsEveryValidationProblemWithTheSamePathsAndMessages() {
        byte[] json = scene(i -> switch (i) {
            case 3 -> "{\"type\": \"sphere\", \"radius\": -1}";
            case 700 -> "{\"type\": \"sphere\", \"material\": {\"type\": \"chalk\", \"color\": \"red\"}}";
            case 900 -> "null";
            case 1400 -> "{\"type\": \"box\", \"size\": [1, 0, 1]}";
            default -> sphere(i);
        });
        List<FieldProblem> parallel = problems(PARALLEL, json);
        assertThat(parallel).isEqualTo(problems(IN_ONE_PIECE, json));
        assertThat(parallel).extracting(FieldProblem::field).containsExactly("objects[1400].size[1]",
                "objects[3].radius", "objects[700].material.color", "objects[900]");
    }

    @Test
    void reportsTheSameBindingProblem() {
        for (String bad : List.of("{\"type\": \"cone\"}", "{\"radius\": 1}", "{\"type\": \"sphere\", \"radius\": \"1\"}",
                "{\"type\": \"sphere\", \"colour\": 1}", "5", "{\"type\": \"sphere\", \"center\": [1, 2]}")) {
            byte[] json = scene(i -> i == 1234 ? bad : sphere(i));
            assertThat(problems(PARALLEL, json)).as(bad).isEqualTo(problems(IN_ONE_PIECE, json));
            assertThat(problems(PARALLEL, json).get(0).field()).as(bad).startsWith("objects[1234]");
        }
    }

    private static List<FieldProblem> problems(SceneReader reader, byte[] json) {
        return catchThrowableOfType(InvalidSceneException.class, () -> reader.read(json)).problems();
    }
}
