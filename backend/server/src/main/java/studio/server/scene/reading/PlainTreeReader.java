package studio.server.scene.reading;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.ObjectReadContext;
import tools.jackson.core.StreamReadFeature;
import tools.jackson.core.json.JsonFactory;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.node.ArrayNode;
import tools.jackson.databind.node.JsonNodeFactory;
import tools.jackson.databind.node.ObjectNode;

/**
 * Reads a well-formed JSON object into Jackson's tree with the streaming parser alone, the same
 * nodes {@link SceneReader}'s mapper reads (an int, long or big integer node by the number's size,
 * a double node for any fraction or exponent; duplicate keys refused), or answers null for anything
 * else: malformed JSON, a root that is not an object, content after it. {@link SceneReader} then
 * reads the bytes again through its mapper, which names the problem.
 *
 * <p>For the command line: {@code bin/studio render scenes/still-life.json --width 160 --height 120 --samples 1}
 * takes 430 ms against 523 through the mapper, cold; warm, even ({@code SceneTreeBench}).
 * {@code PlainTreeReaderTest} checks the trees are equal, node type for node type, to the mapper's.
 */
final class PlainTreeReader {

    private static final JsonFactory FAST_DOUBLES = factory(true), JDK_DOUBLES = factory(false);
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private PlainTreeReader() {
    }

    /**
     * Jackson's parser with or without its own parser of fractions. Both round correctly, so they
     * give the same doubles; Jackson's is the faster warm (a 10,000-sphere scene's tree in 4.2 ms
     * against 6.0) but its first long number brings up the foreign-memory API and its method
     * handles, which cost a one-scene process some 17 ms.
     */
    private static JsonFactory factory(boolean fastDoubles) {
        return JsonFactory.builder()
                .configure(StreamReadFeature.USE_FAST_DOUBLE_PARSER, fastDoubles)
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                .build();
    }

    /**
     * The JSON object in {@code json} as a tree, or null: let the mapper read it.
     *
     * @param fastDoubles whether fractions are parsed by Jackson's parser (for a long-lived process)
     *                    or the JDK's (for one that reads one scene)
     */
    static ObjectNode read(byte[] json, boolean fastDoubles) {
        try (JsonParser parser = (fastDoubles ? FAST_DOUBLES : JDK_DOUBLES).createParser(ObjectReadContext.empty(), json)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return null;
            }
            ObjectNode root = object(parser);
            return parser.nextToken() == null ? root : null;
        } catch (JacksonException e) {
            return null;
        }
    }

    /** The object whose START_OBJECT the parser is at, up to its END_OBJECT. */
    private static ObjectNode object(JsonParser parser) {
        ObjectNode object = NODES.objectNode();
        String name;
        while ((name = parser.nextName()) != null) {
            object.set(name, value(parser, parser.nextToken()));
        }
        return object;
    }

    private static ArrayNode array(JsonParser parser) {
        ArrayNode array = NODES.arrayNode();
        JsonToken token;
        while ((token = parser.nextToken()) != JsonToken.END_ARRAY) {
            array.add(value(parser, token));
        }
        return array;
    }

    private static JsonNode value(JsonParser parser, JsonToken token) {
        return switch (token) {
            case START_OBJECT -> object(parser);
            case START_ARRAY -> array(parser);
            case VALUE_STRING -> NODES.stringNode(parser.getString());
            case VALUE_NUMBER_INT -> switch (parser.getNumberType()) {
                case INT -> NODES.numberNode(parser.getIntValue());
                case LONG -> NODES.numberNode(parser.getLongValue());
                default -> NODES.numberNode(parser.getBigIntegerValue());
            };
            case VALUE_NUMBER_FLOAT -> NODES.numberNode(parser.getDoubleValue());
            case VALUE_TRUE -> NODES.booleanNode(true);
            case VALUE_FALSE -> NODES.booleanNode(false);
            case VALUE_NULL -> NODES.nullNode();
            default -> throw new IllegalStateException("unexpected token in well-formed JSON: " + token);
        };
    }
}
