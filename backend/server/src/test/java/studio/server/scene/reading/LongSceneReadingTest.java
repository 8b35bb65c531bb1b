package studio.server.scene.reading;

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

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDto;

/**
 * A long object list: the fast path and the full path read the same scene, and every problem is
 * named with its object's index, several null fields deep in the list among them.
 */
class LongSceneReadingTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader FAST = new SceneReader(VALIDATION::getValidator, true, true);
    private static final SceneReader FULL = new SceneReader(VALIDATION::getValidator, false, true);
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
    void bothPathsReadTheSameLongScene() {
        byte[] json = scene(i -> i % 3 == 0 ? sphere(i) : i % 3 == 1
                ? "{\"type\": \"box\", \"center\": [0, " + i + ", 0], \"size\": [1, 2, 3], \"rotation\": [0, 45, 0]}"
                : "{\"type\": \"plane\", \"point\": [0, 0, " + i + "], \"normal\": [0, 1, 0]}");
        SceneDto fast = FAST.read(json);
        assertThat(fast).isEqualTo(FULL.read(json));
        assertThat(fast.objects()).hasSize(N);
        assertThat(fast.objects().get(N - 2)).isInstanceOf(ObjectDto.Box.class);
    }

    @Test
    void reportsEveryValidationProblemWithTheSamePathsAndMessages() {
        byte[] json = scene(i -> switch (i) {
            case 3 -> "{\"type\": \"sphere\", \"radius\": -1}";
            case 700 -> "{\"type\": \"sphere\", \"material\": {\"type\": \"chalk\", \"color\": \"red\"}}";
            case 900 -> "null";
            case 1400 -> "{\"type\": \"box\", \"size\": [1, 0, 1]}";
            case 1401 -> "{\"type\": \"box\", \"rotation\": null, \"material\": {\"type\": \"chalk\", \"diffuse\": null}}";
            default -> sphere(i);
        });
        List<FieldProblem> problems = problems(FAST, json);
        assertThat(problems).isEqualTo(problems(FULL, json));
        assertThat(problems).extracting(FieldProblem::field).containsExactly("objects[1400].size[1]",
                "objects[1401].material.diffuse", "objects[1401].rotation", "objects[3].radius",
                "objects[700].material.color", "objects[900]");
    }

    @Test
    void reportsTheSameBindingProblem() {
        for (String bad : List.of("{\"type\": \"cone\"}", "{\"radius\": 1}", "{\"type\": \"sphere\", \"radius\": \"1\"}",
                "{\"type\": \"sphere\", \"colour\": 1}", "5", "{\"type\": \"sphere\", \"center\": [1, 2]}")) {
            byte[] json = scene(i -> i == 1234 ? bad : sphere(i));
            assertThat(problems(FAST, json)).as(bad).isEqualTo(problems(FULL, json));
            assertThat(problems(FAST, json).get(0).field()).as(bad).startsWith("objects[1234]");
        }
    }

    private static List<FieldProblem> problems(SceneReader reader, byte[] json) {
        return catchThrowableOfType(InvalidSceneException.class, () -> reader.read(json)).problems();
    }
}
