package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;

import studio.server.scene.examples.ExampleSceneFiles;

/**
 * {@link PlainTreeReader} reads exactly the tree {@link SceneReader}'s mapper reads, node class for
 * node class, with Jackson's parser of fractions and with the JDK's, or leaves the bytes to the
 * mapper.
 */
class PlainTreeReaderTest {

    private static final JsonMapper MAPPER = SceneReader.FullPath.MAPPER;

    @Test
    void readsEveryExampleSceneAsTheMapperDoes() throws IOException {
        List<Path> files = new ArrayList<>(ExampleSceneFiles.all());
        try (Stream<Path> bench = Files.list(ExampleSceneFiles.dir().resolve("bench"))) {
            bench.filter(p -> p.toString().endsWith(".json")).forEach(files::add);
        }
        assertThat(files).hasSizeGreaterThanOrEqualTo(10);
        for (Path file : files) {
            assertSameTree(Files.readAllBytes(file));
        }
    }

    @Test
    void readsEveryKindOfNumberAsTheMapperDoes() {
        String numbers = String.join(", ", "0", "-0", "1", "-1", "0.0", "-0.0", "1.5", "1e5", "1E-5", "-2.5e+3",
                "2147483647", "-2147483648", "2147483648", "-2147483649", "9223372036854775807",
                "-9223372036854775808", "9223372036854775808", "123456789012345678901234567890", "1e400", "-1e400",
                "4.9e-324", "1e-400", "0.1", "0.30000000000000004", "-49.444764", "3.141592653589793238462643");
        JsonNode tree = assertSameTree(("{\"n\": [" + numbers + "], \"one\": 7, \"big\": 1e309}")
                .getBytes(StandardCharsets.UTF_8));
        assertThat(tree.get("n").get(12).isLong()).isTrue();
        assertThat(tree.get("n").get(16).isBigInteger()).isTrue();
        assertThat(tree.get("n").get(2).isInt()).isTrue();
        assertThat(tree.get("n").get(4).isDouble()).isTrue();
    }

    @Test
    void readsStringsLiteralsAndNestingAsTheMapperDoes() {
        assertSameTree("""
                {"s": "a\\"b\\\\c\\n\\u00e9\\ud83d\\ude00 é", "t": true, "f": false, "z": null, "e": {}, "a": [],
                 "deep": [[[{"x": [1, [2, {"y": null}]]}]]], "": "empty key", "k": "v"}""".getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void readsRandomDocumentsAsTheMapperDoes() {
        Random random = new Random(20261203);
        for (int i = 0; i < 2000; i++) {
            StringBuilder json = new StringBuilder();
            randomObject(random, json, 0);
            assertSameTree(json.toString().getBytes(StandardCharsets.UTF_8));
        }
    }

    @Test
    void leavesToTheMapperWhatIsNotOneWellFormedObject() {
        for (String bad : List.of("", "   ", "[]", "[{}]", "1", "\"scene\"", "null", "{} x", "{}{}", "{} []",
                "{\"a\": 1, \"a\": 2}", "{\"o\": {\"b\": 1, \"b\": 1}}", "{\"a\":}", "{\"a\": 1", "{\"a\": [1, 2}",
                "{\"a\": 01}", "{\"a\": NaN}", "{'a': 1}", "{a: 1}", "{\"a\": 1,}", "{\"a\": \"\u0001\"}",
                "{\"a\": 1} // comment")) {
            for (boolean fastDoubles : new boolean[] {true, false}) {
                assertThat(PlainTreeReader.read(bad.getBytes(StandardCharsets.UTF_8), fastDoubles)).as(bad).isNull();
            }
        }
        String deep = "{\"a\": " + "[".repeat(5000) + "]".repeat(5000) + "}";
        assertThat(PlainTreeReader.read(deep.getBytes(StandardCharsets.UTF_8), true)).isNull();
    }

    /**
     * The plain reader's tree, with either parser of fractions, asserted equal to the mapper's with
     * every node of the same class.
     */
    private static JsonNode assertSameTree(byte[] json) {
        JsonNode mapped = MAPPER.readTree(json);
        JsonNode plain = null;
        for (boolean fastDoubles : new boolean[] {true, false}) {
            plain = PlainTreeReader.read(json, fastDoubles);
            assertThat(plain).as(new String(json, StandardCharsets.UTF_8)).isNotNull().isEqualTo(mapped);
            assertSameClasses(plain, mapped);
        }
        return plain;
    }

    private static void assertSameClasses(JsonNode a, JsonNode b) {
        assertThat(a.getClass()).isEqualTo(b.getClass());
        if (a.isObject()) {
            Iterator<Map.Entry<String, JsonNode>> ia = a.properties().iterator(), ib = b.properties().iterator();
            while (ia.hasNext()) {
                Map.Entry<String, JsonNode> ea = ia.next(), eb = ib.next();
                assertThat(ea.getKey()).isEqualTo(eb.getKey());
                assertSameClasses(ea.getValue(), eb.getValue());
            }
            assertThat(ib.hasNext()).isFalse();
        } else if (a.isArray()) {
            for (int i = 0; i < a.size(); i++) {
                assertSameClasses(a.get(i), b.get(i));
            }
        }
    }

    private static void randomObject(Random random, StringBuilder out, int depth) {
        out.append('{');
        int members = random.nextInt(depth == 0 ? 6 : 4);
        for (int i = 0; i < members; i++) {
            out.append(i > 0 ? ", " : "").append("\"k").append(i).append("\": ");
            randomValue(random, out, depth + 1);
        }
        out.append('}');
    }

    private static void randomValue(Random random, StringBuilder out, int depth) {
        int kind = random.nextInt(depth > 4 ? 6 : 8);
        switch (kind) {
            case 0 -> out.append(random.nextInt());
            case 1 -> out.append(random.nextLong());
            case 2 -> out.append(random.nextGaussian() * Math.pow(10, random.nextInt(40) - 20));
            case 3 -> out.append(String.format(java.util.Locale.ROOT, "%.6f", (random.nextDouble() - 0.5) * 100));
            case 4 -> out.append('"').append(Long.toString(random.nextLong(), 36)).append('"');
            case 5 -> out.append(random.nextBoolean() ? "true" : random.nextBoolean() ? "false" : "null");
            case 6 -> {
                out.append('[');
                for (int i = random.nextInt(4); i > 0; i--) {
                    randomValue(random, out, depth + 1);
                    out.append(i > 1 ? ", " : "");
                }
                out.append(']');
            }
            default -> randomObject(random, out, depth);
        }
    }
}
