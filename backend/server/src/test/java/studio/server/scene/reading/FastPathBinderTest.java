package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;

import jakarta.validation.ValidatorFactory;
import jakarta.validation.Validation;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

import studio.server.scene.examples.ExampleSceneFiles;
import studio.server.scene.format.InvalidSceneException;
import studio.server.scene.format.SceneDto;

/**
 * The fast path may only ever be stricter than the full path: on every scene it either answers
 * exactly what Jackson's binding and Hibernate Validator answer, or leaves the scene to them.
 * Checked on the example scenes and on thousands of mutations of them (wrong types, values out of
 * range or at their bounds, unknown and missing fields, nulls, other type ids).
 */
class FastPathBinderTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader FAST = new SceneReader(VALIDATION::getValidator, true, true);
    private static final SceneReader FULL = new SceneReader(VALIDATION::getValidator, false, true);
    private static final FastPathBinder BINDER = new FastPathBinder(SceneDto.class);
    private static final JsonMapper JSON = JsonMapper.builder().build();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static List<Path> exampleScenes() throws IOException {
        List<Path> files = new ArrayList<>(ExampleSceneFiles.all());
        try (Stream<Path> bench = Files.list(ExampleSceneFiles.dir().resolve("bench"))) {
            bench.filter(p -> p.toString().endsWith(".json")).sorted().forEach(files::add);
        }
        return files;
    }

    @Test
    void takesEveryExampleSceneAndBindsWhatTheFullPathBinds() throws IOException {
        List<Path> files = exampleScenes();
        assertThat(files).hasSizeGreaterThanOrEqualTo(10);
        for (Path file : files) {
            byte[] json = Files.readAllBytes(file);
            SceneDto fast = BINDER.bind(JSON.readTree(json));
            assertThat(fast).as(file.toString()).isNotNull().isEqualTo(FULL.read(json));
        }
    }

    @Test
    void leavesEveryBrokenRuleToTheFullPath() {
        String scene = """
                {"image": {"width": 320, "height": 240, "quality": 0.9},
                 "camera": {"position": [0, 1, 5], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
                 "render": {"sampler": "sobol", "samples": 16, "adaptive": 0.05},
                 "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                              "material": {"type": "plastic", "color": "#336699", "shininess": 20}}]}""";
        assertThat((Object) BINDER.bind(JSON.readTree(scene))).isNotNull();
        for (String broken : List.of(
                "\"radius\": 1,|\"radius\": 0,", "\"radius\": 1,|\"radius\": -1,", "\"radius\": 1,|\"radius\": \"1\",",
                "\"fov\": 40|\"fov\": 180", "\"fov\": 40|\"fov\": 0", "\"shininess\": 20|\"shininess\": 0.5",
                "\"quality\": 0.9|\"quality\": 1.5", "\"width\": 320|\"width\": 320.0", "\"width\": 320|\"width\": 0",
                "\"up\": [0, 1, 0]|\"up\": [0, 0, 0]", "\"lookAt\": [0, 0, 0]|\"lookAt\": [0, 0]",
                "#336699|#33669", "\"sobol\"|\"halton\"", "\"type\": \"plastic\"|\"type\": \"rubber\"",
                "\"center\": [0, 0, 0]|\"center\": [0, null, 0]", "\"radius\": 1,|\"radius\": 1, \"size\": 2,",
                "\"adaptive\": 0.05|\"adaptive\": 1e400", "\"samples\": 16|\"samples\": 4294967296")) {
            String[] change = broken.split("\\|");
            String json = scene.replace(change[0], change[1]);
            assertThat(json).isNotEqualTo(scene);
            assertThat((Object) BINDER.bind(JSON.readTree(json))).as(change[1]).isNull();
            assertThatThrownBy(() -> FULL.read(json.getBytes(StandardCharsets.UTF_8)))
                    .as(change[1]).isInstanceOf(InvalidSceneException.class);
        }
    }

    @Test
    void answersWhatTheFullPathAnswersOnThousandsOfMutatedScenes() throws IOException {
        List<JsonNode> scenes = new ArrayList<>();
        for (Path file : exampleScenes()) {
            JsonNode tree = JSON.readTree(Files.readAllBytes(file));
            // meshes' OBJ text is long and checked by the mapper, not here
            if (!tree.toString().contains("\"mesh\"")) {
                scenes.add(tree);
            }
        }
        Random random = new Random(20261122);
        int accepted = 0, refused = 0;
        for (int round = 0; round < 4000; round++) {
            JsonNode tree = scenes.get(random.nextInt(scenes.size())).deepCopy();
            for (int m = 1 + random.nextInt(2); m > 0; m--) {
                mutate(tree, random);
            }
            byte[] json = JSON.writeValueAsBytes(tree);
            Object fast = outcome(FAST, json), full = outcome(FULL, json);
            assertThat(fast).as(new String(json, StandardCharsets.UTF_8)).isEqualTo(full);
            if (full instanceof SceneDto) {
                accepted++;
            } else {
                refused++;
            }
        }
        // both kinds of outcome must be well represented for the comparison to mean anything
        assertThat(accepted).isGreaterThan(1000);
        assertThat(refused).isGreaterThan(1000);
    }

    /** The scene, or the problems it was refused with. */
    private static Object outcome(SceneReader reader, byte[] json) {
        try {
            return reader.read(json, Map.of());
        } catch (InvalidSceneException e) {
            return e.problems();
        }
    }

    /** Nudges a number, or replaces, removes or adds one value somewhere in the tree. */
    private static void mutate(JsonNode tree, Random random) {
        List<JsonNode> containers = new ArrayList<>();
        collect(tree, containers);
        JsonNode container = containers.get(random.nextInt(containers.size()));
        if (random.nextInt(10) < 4) {
            nudgeANumber(container, random);
        } else if (container instanceof ObjectNode object) {
            List<String> names = new ArrayList<>(object.propertyNames());
            int kind = random.nextInt(10);
            if (kind == 0 || names.isEmpty()) {
                object.set(random.nextBoolean() ? "extra" : "radius", value(random));
            } else if (kind == 1) {
                object.remove(names.get(random.nextInt(names.size())));
            } else {
                object.set(names.get(random.nextInt(names.size())), value(random));
            }
        } else if (container instanceof ArrayNode array && !array.isEmpty()) {
            int i = random.nextInt(array.size());
            int kind = random.nextInt(10);
            if (kind == 0) {
                array.remove(i);
            } else if (kind == 1) {
                array.add(array.get(i).deepCopy());
            } else {
                array.set(i, value(random));
            }
        }
    }

    /** A number in the container becomes a nearby one of the same kind (most scenes stay valid). */
    private static void nudgeANumber(JsonNode container, Random random) {
        List<Object> keys = new ArrayList<>();
        if (container instanceof ObjectNode object) {
            object.propertyNames().stream().filter(k -> object.get(k).isNumber()).forEach(keys::add);
        } else {
            for (int i = 0; i < container.size(); i++) {
                if (container.get(i).isNumber()) {
                    keys.add(i);
                }
            }
        }
        if (keys.isEmpty()) {
            return;
        }
        Object key = keys.get(random.nextInt(keys.size()));
        JsonNode old = key instanceof String name ? container.get(name) : container.get((Integer) key);
        JsonNode nudged = old.isInt() ? NODES.numberNode(Math.max(1, old.intValue() + random.nextInt(3) - 1))
                : NODES.numberNode(old.doubleValue() * (0.5 + random.nextDouble()) + (random.nextDouble() - 0.5) * 0.1);
        if (container instanceof ObjectNode object) {
            object.set((String) key, nudged);
        } else {
            ((ArrayNode) container).set((Integer) key, nudged);
        }
    }

    private static void collect(JsonNode node, List<JsonNode> containers) {
        if (node.isContainer()) {
            containers.add(node);
            for (JsonNode child : node) {
                collect(child, containers);
            }
        }
    }

    /** A value that fits somewhere in a scene, or nearly. */
    private static JsonNode value(Random random) {
        return switch (random.nextInt(16)) {
            case 0 -> NODES.numberNode(new int[] {-1, 0, 1, 2, 3, 16, 200, 10000}[random.nextInt(8)]);
            case 1 -> NODES.numberNode(new double[] {-0.0, 0.0, 0.5, 1.0, 1.5, 1e-9, -2.5, 4.0, 179.99, 180.0,
                    1e4, 1e6, 1.0000001e6, Double.POSITIVE_INFINITY, Double.NaN}[random.nextInt(15)]);
            case 2 -> NODES.numberNode(1L << 40);
            case 3 -> NODES.textNode(new String[] {"#12abEF", "#12345", "#12345g", "sphere", "box", "plane", "glass",
                    "chalk", "mirror", "jpg", "png", "sobol", "jittered", "x", ""}[random.nextInt(15)]);
            case 4 -> NODES.booleanNode(random.nextBoolean());
            case 5 -> NODES.nullNode();
            case 6 -> NODES.arrayNode();
            case 7 -> NODES.arrayNode().add(random.nextDouble() * 4 - 2).add(random.nextInt(3)).add(0.25);
            case 8 -> NODES.arrayNode().add(0).add(0).add(0);
            case 9 -> NODES.arrayNode().add(1).add(2);
            case 10 -> NODES.arrayNode().add(1).addNull().add(2);
            case 11 -> NODES.objectNode();
            case 12 -> NODES.objectNode().put("type", new String[] {"chalk", "metal", "glass", "flat"}[random.nextInt(4)])
                    .put("color", "#a0b1c2");
            case 13 -> NODES.objectNode().put("type", "sphere").put("radius", 0.5)
                    .set("center", NODES.arrayNode().add(0).add(1).add(2));
            case 14 -> NODES.numberNode(random.nextDouble());
            default -> NODES.numberNode(random.nextInt(5) + 0.5);
        };
    }
}
