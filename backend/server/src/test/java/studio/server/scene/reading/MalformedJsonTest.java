package studio.server.scene.reading;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Locale;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.hibernate.validator.HibernateValidator;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import jakarta.validation.Validation;
import jakarta.validation.ValidatorFactory;

import studio.server.scene.format.FieldProblem;
import studio.server.scene.format.InvalidSceneException;

/**
 * Scene JSON the parser cannot read: the one problem names the JSON path where the parser stopped
 * (the field being read, or the object or array between whose entries it failed) and says why in
 * the user's words, never in the parser's (its classes, methods, features and token names).
 */
class MalformedJsonTest {

    private static final ValidatorFactory VALIDATION = Validation.byProvider(HibernateValidator.class).configure()
            .defaultLocale(Locale.ENGLISH).buildValidatorFactory();
    private static final SceneReader FAST = new SceneReader(VALIDATION::getValidator, true, true);
    private static final SceneReader FULL = new SceneReader(VALIDATION::getValidator, false, true);

    /** What gives a message away as the library's rather than the user's. */
    private static final Pattern LIBRARY_WORDS = Pattern.compile("`|Feature|[A-Z]+_[A-Z]+|\\w\\(\\)|java\\.|jackson"
            + "|Exception|StreamRead|JsonToken|Source|code \\d|\\(CTRL-CHAR|Object entries|Array entries|property name");

    @AfterAll
    static void close() {
        VALIDATION.close();
    }

    private static byte[] utf8(String json) {
        return json.getBytes(StandardCharsets.UTF_8);
    }

    /** {@code before}, then the raw bytes, then {@code after}: JSON that is not valid UTF-8. */
    private static byte[] withBytes(String before, byte[] raw, String after) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(utf8(before));
        out.writeBytes(raw);
        out.writeBytes(utf8(after));
        return out.toByteArray();
    }

    /** The one problem of a body, the same on both reading paths. */
    private static FieldProblem onlyProblem(byte[] body) {
        InvalidSceneException fast = catchThrowableOfType(InvalidSceneException.class, () -> FAST.read(body));
        InvalidSceneException full = catchThrowableOfType(InvalidSceneException.class, () -> FULL.read(body));
        assertThat(fast).as("refused").isNotNull();
        assertThat(full).as("refused on the full path").isNotNull();
        assertThat(fast.problems()).isEqualTo(full.problems()).hasSize(1);
        return fast.problems().get(0);
    }

    private static FieldProblem onlyProblem(String body) {
        return onlyProblem(utf8(body));
    }

    private static void assertProblem(String body, String field, String message) {
        assertThat(onlyProblem(body)).isEqualTo(new FieldProblem(field, message));
    }

    // --- duplicate keys: the duplicated field's path ---------------------------------------------

    @Test
    void namesDuplicateTopLevelField() {
        assertProblem("{\"name\":\"a\",\"objects\":[],\"name\":\"b\"}", "name",
                "malformed JSON at line 1, column 32: the field is given twice; each field may appear once");
    }

    @Test
    void namesDuplicateFieldDeepInTheScene() {
        FieldProblem problem = onlyProblem("{\"objects\":[{\"type\":\"sphere\",\"radius\":1,\"material\":"
                + "{\"type\":\"chalk\",\"color\":\"#ffffff\",\"color\":\"#000000\"}}]}");
        assertThat(problem.field()).isEqualTo("objects[0].material.color");
        assertThat(problem.message()).endsWith("the field is given twice; each field may appear once");
    }

    @Test
    void namesDuplicateThatFollowsItsTwin() {
        assertThat(onlyProblem("{\"image\":{\"width\":8,\"width\":9},\"objects\":[]}").field()).isEqualTo("image.width");
    }

    @Test
    void namesDuplicateInALaterElement() {
        assertThat(onlyProblem("{\"objects\":[{\"type\":\"sphere\"},{\"type\":\"sphere\",\"radius\":1,\"radius\":2}]}")
                .field()).isEqualTo("objects[1].radius");
    }

    // --- limits: where they were passed, said without the parser's names -------------------------

    @Test
    void namesWhereTheNestingLimitWasPassed() {
        FieldProblem problem = onlyProblem("{\"objects\":[],\"render\":" + "{\"a\":".repeat(600) + "1"
                + "}".repeat(600) + "}");
        assertThat(problem.message()).startsWith("the scene is nested deeper than 500 levels (at line 1, column ");
        // render.a.a…: 499 levels below render, its middle left out
        assertThat(problem.field()).startsWith("render.a.a.a.a").endsWith(".a.a.a").contains("…")
                .hasSizeLessThanOrEqualTo(MalformedJson.MAX_PATH_LENGTH);
    }

    @Test
    void namesWhereNestedArraysPassTheLimit() {
        FieldProblem problem = onlyProblem("{\"objects\":" + "[".repeat(100_000) + "]".repeat(100_000) + "}");
        assertThat(problem.field()).startsWith("objects[0][0][0]").endsWith("[0][0]").contains("…");
        assertThat(problem.message()).startsWith("the scene is nested deeper than 500 levels");
    }

    @Test
    void keepsAPathWithinBoundsWhenEveryLevelHasAHugeName() {
        String name = "n".repeat(40_000);
        FieldProblem problem = onlyProblem("{\"objects\":[],\"render\":" + ("{\"" + name + "\":").repeat(501) + "1"
                + "}".repeat(501) + "}");
        assertThat(problem.field()).startsWith("render…nnn").hasSizeLessThanOrEqualTo(MalformedJson.MAX_PATH_LENGTH);
    }

    @Test
    void namesTheFieldOfANumberTooLong() {
        assertProblem("{\"camera\":{\"fov\":" + "1".repeat(5_000) + "},\"objects\":[]}", "camera.fov",
                "the number is longer than 1000 characters (at line 1, column 5018)");
    }

    @Test
    void namesTheElementOfANumberTooLong() {
        assertThat(onlyProblem("{\"camera\":{\"position\":[0,0." + "5".repeat(5_000) + ",0]},\"objects\":[]}").field())
                .isEqualTo("camera.position[1]");
    }

    @Test
    void namesTheObjectOfAFieldNameTooLong() {
        FieldProblem problem = onlyProblem("{\"objects\":[{\"type\":\"sphere\",\"" + "n".repeat(60_000) + "\":1}]}");
        assertThat(problem.field()).isEqualTo("objects[0]");
        assertThat(problem.message()).startsWith("the field name is longer than 50000 characters");
    }

    // --- invalid UTF-8: the field being read -----------------------------------------------------

    @Test
    void namesTheFieldOfTextThatIsNotUtf8() {
        byte[] body = withBytes("{\"name\":\"a", new byte[] {(byte) 0xC3, 0x28}, "b\",\"objects\":[]}");
        assertThat(onlyProblem(body)).isEqualTo(new FieldProblem("name",
                "malformed JSON at line 1, column 13: the text is not valid UTF-8; send the scene encoded as UTF-8"));
    }

    @Test
    void namesTheFieldOfNonUtf8TextDeepInTheScene() {
        byte[] body = withBytes("{\"objects\":[{\"type\":\"mesh\",\"obj\":\"v 0 0 0 ", new byte[] {(byte) 0xFF}, "\"}]}");
        assertThat(onlyProblem(body).field()).isEqualTo("objects[0].obj");
    }

    @Test
    void namesTheElementOfNonUtf8Text() {
        byte[] body = withBytes("{\"objects\":[\"a\",\"", new byte[] {(byte) 0xFF}, "\"]}");
        assertThat(onlyProblem(body).field()).isEqualTo("objects[1]");
    }

    @Test
    void namesTheObjectOfAFieldNameThatIsNotUtf8RightAfterATextValue() {
        byte[] body = withBytes("{\"objects\":[{\"type\":\"sphere\",\"na", new byte[] {(byte) 0xFF}, "me\":1}]}");
        FieldProblem problem = onlyProblem(body);
        assertThat(problem.field()).isEqualTo("objects[0]");
        assertThat(problem.message()).contains("not valid UTF-8");
    }

    // --- the parser's messages in the user's words -----------------------------------------------

    @Test
    void saysNanIsNoJsonNumber() {
        assertProblem("{\"camera\":{\"fov\":NaN},\"objects\":[]}", "camera.fov",
                "malformed JSON at line 1, column 21: NaN and Infinity are not JSON numbers; write a number");
    }

    @Test
    void saysInfinityIsNoJsonNumberInAVector() {
        FieldProblem problem = onlyProblem("{\"camera\":{\"position\":[-Infinity,0,0]},\"objects\":[]}");
        assertThat(problem.field()).isEqualTo("camera.position[0]");
        assertThat(problem.message()).endsWith("NaN and Infinity are not JSON numbers; write a number");
    }

    @Test
    void namesTheElementOfAnUnknownWord() {
        assertProblem("{\"objects\":[tru]}", "objects[0]", "malformed JSON at line 1, column 13: 'tru' is not a JSON "
                + "value; expected a value (a string, number, array, object, true, false or null)");
    }

    @Test
    void namesTheObjectMissingACommaBetweenItsFields() {
        assertProblem("{\"objects\":[{\"type\":\"sphere\" \"radius\":1}]}", "objects[0]",
                "malformed JSON at line 1, column 30: unexpected '\"'; expected a comma between the fields");
    }

    @Test
    void namesTheFieldMissingItsColon() {
        assertProblem("{\"objects\" []}", "objects",
                "malformed JSON at line 1, column 12: unexpected '['; expected a colon after the field name");
    }

    @Test
    void namesTheArrayClosedWithABrace() {
        assertProblem("{\"objects\":[}", "objects",
                "malformed JSON at line 1, column 13: unexpected '}'; expected ']' to close the array");
    }

    @Test
    void saysCommentsAreNotJson() {
        assertProblem("{\"objects\":[] /* none */}", "",
                "malformed JSON at line 1, column 15: comments are not allowed in JSON");
    }

    @Test
    void namesTheFieldOfABadEscape() {
        assertProblem("{\"name\":\"a\\qb\",\"objects\":[]}", "name", "malformed JSON at line 1, column 12: \\q is not "
                + "a JSON escape; the escapes are \\\", \\\\, \\/, \\b, \\f, \\n, \\r, \\t and \\uXXXX");
    }

    @Test
    void namesTheFieldOfAControlCharacterInText() {
        assertProblem("{\"name\":\"a\u0001b\",\"objects\":[]}", "name", "malformed JSON at line 1, column 11: the "
                + "control character U+0001 must be escaped in a string (as \\n, \\t or \\u00XX)");
    }

    @Test
    void namesTheFieldOfANumberWithALeadingZeroOrPlus() {
        assertThat(onlyProblem("{\"camera\":{\"fov\":012},\"objects\":[]}"))
                .isEqualTo(new FieldProblem("camera.fov", "malformed JSON at line 1, column 19: a number may not start "
                        + "with 0 (write 12, not 012)"));
        assertThat(onlyProblem("{\"camera\":{\"fov\":+1},\"objects\":[]}"))
                .isEqualTo(new FieldProblem("camera.fov", "malformed JSON at line 1, column 19: a number may not start "
                        + "with '+'; leave the sign out"));
    }

    @Test
    void saysWhereTheSceneEndsTooEarly() {
        assertProblem("{\"name\":\"abc", "name", "malformed JSON at line 1, column 13: the scene ends inside a string");
        assertThat(onlyProblem("{\"objects\":[{\"type\":\"sphere\",").message())
                .endsWith("the scene ends before every object and array in it is closed");
    }

    @Test
    void saysWhatFollowsTheSceneIsUnexpected() {
        assertProblem("{\"objects\":[]} xyz", "",
                "malformed JSON at line 1, column 16: unexpected content after the scene's closing '}'");
    }

    // --- no message names the library ------------------------------------------------------------

    static Stream<Arguments> malformed() {
        return Stream.of(
                "{\"objects\":[], \"a\":NaN}", "{\"objects\":[], \"a\":-Infinity}", "{\"objects\":[], \"a\":+Infinity}",
                "{\"objects\":[], \"a\":+1}", "{\"objects\":[], \"a\":01}", "{\"objects\":[], \"a\":1.}",
                "{\"objects\":[], \"a\":1e}", "{\"objects\":[], \"a\":-}", "{\"objects\":[], \"a\":.5}",
                "{\"objects\":[], \"a\":0x10}", "{\"objects\":[], \"a\":tru}", "{\"objects\":[], \"a\":nul}",
                "{\"objects\":[], \"a\":'x'}", "{'objects':[]}", "{objects:[]}", "{\"objects\":[],}", "{\"objects\":[1,]}",
                "{\"objects\":[1 2]}", "{\"objects\" []}", "{\"objects\":[}", "{\"objects\":]}", "{\"objects\":[]}}",
                "{\"objects\":[] // c\n}", "{\"objects\":[] /* c */}", "{\"objects\":[] #c\n}", "{\"objects\":[], \"a",
                "{\"objects\":[], \"a\":\"x", "{\"objects\":[], \"a\":\"\\u12", "{\"objects\":[], \"a\":\"\\", "{\"objects\":[",
                "{\"objects\":[], \"a\":\"\\x\"}", "{\"objects\":[], \"a\":\"\\u12zz\"}", "{\"objects\":[], \"a\":\"\t\"}",
                "{\"objects\":[]\u0000}", "{\"objects\":[]} 1", "{\"objects\":[]} {}", "{\"objects\":[]} xyz", "{\"a\":1,\"a\":2}",
                "{\"objects\":[], \"a\":" + "9".repeat(1_001) + "}", "{\"objects\":[], \"a\":0." + "9".repeat(1_001) + "}",
                "{\"" + "n".repeat(50_001) + "\":1}", "{\"objects\":" + "[".repeat(501) + "]".repeat(501) + "}",
                "{\"objects\":[], \"a\":1e999999999999}", "123abc", "[1,2", "\"unclosed", "{\"objects\":[]}garbage")
                .map(Arguments::of);
    }

    @ParameterizedTest
    @MethodSource("malformed")
    void saysEveryParserFailureInTheUsersWords(String body) {
        List<FieldProblem> problems = catchThrowableOfType(InvalidSceneException.class, () -> FAST.read(utf8(body)))
                .problems();
        for (FieldProblem problem : problems) {
            assertThat(problem.message()).as(body).doesNotContainPattern(LIBRARY_WORDS).isNotBlank();
        }
    }

    @Test
    void saysNonUtf8AndStrayBytesInTheUsersWords() {
        for (byte[] body : List.of(withBytes("{\"objects\":[], \"a\":\"", new byte[] {(byte) 0x80}, "\"}"),
                withBytes("{\"objects\":[], \"", new byte[] {(byte) 0xE2, (byte) 0x82}, "\":1}"),
                withBytes("{\"objects\":[] ", new byte[] {(byte) 0xFF}, "}"))) {
            FieldProblem problem = catchThrowableOfType(InvalidSceneException.class, () -> FAST.read(body)).problems().get(0);
            assertThat(problem.message()).doesNotContainPattern(LIBRARY_WORDS);
        }
    }
}
