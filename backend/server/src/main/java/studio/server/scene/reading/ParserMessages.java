package studio.server.scene.reading;

import java.util.List;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonToken;
import tools.jackson.core.StreamReadConstraints;
import tools.jackson.core.exc.StreamConstraintsException;
import tools.jackson.core.exc.UnexpectedEndOfInputException;

/**
 * The JSON parser's messages in the user's words. Jackson's name its own classes, methods and
 * features ("enable `JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS` to allow", "from
 * `StreamReadConstraints.getMaxNestingDepth()`", "in VALUE_STRING"), which mean nothing to
 * someone writing a scene. Each kind of message jackson-core 3 writes is matched here and said
 * again; one this table does not know is passed on only if it names nothing of the library, else
 * replaced by a plain "cannot be read" (so a new Jackson message can make a detail vaguer, never
 * leak).
 */
final class ParserMessages {

    private ParserMessages() {
    }

    /** One kind of parser message, and how to say it. */
    private record Rule(Pattern pattern, Function<Matcher, String> words) {
        static Rule of(String regex, Function<Matcher, String> words) {
            return new Rule(Pattern.compile(regex), words);
        }
    }

    private static final String VALUE = "a value (a string, number, array, object, true, false or null)";

    /** Syntax errors, by the start of Jackson's message (its first line, the location trailer removed). */
    private static final List<Rule> SYNTAX = List.of(
            Rule.of("^Duplicate Object property \"(.*)\"$", m -> "the field is given twice; each field may appear once"),
            Rule.of("^Invalid UTF-8 ", m -> "the text is not valid UTF-8; send the scene encoded as UTF-8"),
            Rule.of("^Non-standard token '(.*)'", m -> "NaN and Infinity are not JSON numbers; write a number"),
            Rule.of("numbers to have plus signs", m -> "a number may not start with '+'; leave the sign out"),
            Rule.of("\\(non-standard\\) comment", m -> "comments are not allowed in JSON"),
            Rule.of("Leading zeroes not allowed", m -> "a number may not start with 0 (write 12, not 012)"),
            Rule.of("Decimal point not followed by a digit", m -> "a decimal point must be followed by a digit (write 1.0, "
                    + "not 1.)"),
            Rule.of("Exponent indicator not followed by a digit", m -> "an exponent must have digits (write 1e5, not 1e)"),
            Rule.of("to follow minus sign", m -> "a '-' must be followed by digits"),
            Rule.of("^Unrecognized token '(.*)': was expecting", m -> quoted(m.group(1)) + " is not a JSON value; expected "
                    + VALUE),
            Rule.of("^Unrecognized character escape .*\\(code (\\d+)\\)", m -> escaped(m.group(1))
                    + " is not a JSON escape; the escapes are \\\", \\\\, \\/, \\b, \\f, \\n, \\r, \\t and \\uXXXX"),
            Rule.of("hex-digit for character escape", m -> "a \\u escape takes four hex digits (such as \\u00e9)"),
            Rule.of("^Illegal unquoted character .*code (\\d+)", m -> "the control character " + codePoint(m.group(1))
                    + " must be escaped in a string (as \\n, \\t or \\u00XX)"),
            Rule.of("^Illegal character .*code (\\d+)", m -> "unexpected control character " + codePoint(m.group(1))
                    + "; only spaces, tabs and line breaks may stand between values"),
            Rule.of("^Unexpected close marker '(.)': expected '(.)'", m -> "unexpected '" + m.group(1) + "'; expected '"
                    + m.group(2) + "' to close the " + (m.group(2).equals("}") ? "object" : "array")),
            Rule.of("^Unexpected close marker '(.)': no open", m -> "unexpected '" + m.group(1) + "'; nothing is open "
                    + "to close"),
            Rule.of("^Unexpected character .*code (\\d+).*: was expecting (?:double-quote|either valid name)",
                    m -> "unexpected " + character(m.group(1)) + "; expected a field name in double quotes"),
            Rule.of("^Unexpected character .*code (\\d+).*: was expecting comma to separate Object",
                    m -> "unexpected " + character(m.group(1)) + "; expected a comma between the fields"),
            Rule.of("^Unexpected character .*code (\\d+).*: was expecting comma to separate Array",
                    m -> "unexpected " + character(m.group(1)) + "; expected a comma between the elements"),
            Rule.of("^Unexpected character .*code (\\d+).*: was expecting a colon",
                    m -> "unexpected " + character(m.group(1)) + "; expected a colon after the field name"),
            Rule.of("^Unexpected character .*code (\\d+).*in numeric value",
                    m -> "unexpected " + character(m.group(1)) + " in a number"),
            Rule.of("^Unexpected character .*code (\\d+)", m -> "unexpected " + character(m.group(1)) + "; expected "
                    + VALUE),
            Rule.of("^Unexpected end-of-input.*(VALUE_STRING|character escape)", m -> "the scene ends inside a string"),
            Rule.of("^Unexpected end-of-input.*(property name|for name)", m -> "the scene ends inside a field name"),
            Rule.of("^Unexpected end-of-input.*comment", m -> "the scene ends inside a comment (and comments are not "
                    + "allowed in JSON)"),
            Rule.of("^Unexpected end-of-input", m -> "the scene ends before every object and array in it is closed"),
            Rule.of("^Expected space separating root-level values", m -> "unexpected content after the scene"),
            Rule.of("^Invalid numeric value", m -> "the number is malformed"));

    private static final Pattern LOCATION_TRAILER = Pattern.compile("\\s*(\\(start marker at .*|at \\[Source.*)$");
    /** What gives a message away as the library's: a `code` span, Feature or constant names, method calls. */
    private static final Pattern LIBRARY_WORDS = Pattern.compile(
            "`|Feature|[A-Z]+_[A-Z_]+|\\w\\(\\)|\\bjava\\.|tools\\.jackson|Exception|Current token");

    /**
     * The user's words for a parser failure at the given line and column.
     *
     * @param limits the parser's limits, for the figures of a limit that was passed
     */
    static String describe(JacksonException e, StreamReadConstraints limits, int line, int column) {
        String message = firstLine(e.getOriginalMessage());
        if (e instanceof StreamConstraintsException) {
            return beyondLimit(message, limits) + " (at line " + line + ", column " + column + ")";
        }
        String words = e instanceof UnexpectedEndOfInputException end ? endOfInput(end) : null;
        for (int i = 0; words == null && i < SYNTAX.size(); i++) {
            Matcher m = SYNTAX.get(i).pattern().matcher(message);
            if (m.find()) {
                words = SYNTAX.get(i).words().apply(m);
            }
        }
        return "malformed JSON at line " + line + ", column " + column + ": " + (words != null ? words : plain(message));
    }

    /** Whether the parser failed on a name its object already has. */
    static boolean isDuplicateName(JacksonException e) {
        return firstLine(e.getOriginalMessage()).startsWith("Duplicate Object property");
    }

    /** A message of unknown kind as it is if it names nothing of the library, else a plain one. */
    static String plain(String message) {
        return message.isBlank() || LIBRARY_WORDS.matcher(message).find() ? "this cannot be read as JSON" : message;
    }

    private static String beyondLimit(String message, StreamReadConstraints limits) {
        if (message.startsWith("Document nesting depth")) {
            return "the scene is nested deeper than " + limits.getMaxNestingDepth() + " levels";
        }
        if (message.startsWith("Number value length")) {
            return "the number is longer than " + limits.getMaxNumberLength() + " characters";
        }
        if (message.startsWith("Name length")) {
            return "the field name is longer than " + limits.getMaxNameLength() + " characters";
        }
        if (message.startsWith("String value length")) {
            return "the string is longer than " + limits.getMaxStringLength() + " characters";
        }
        return "the scene is too large to read";
    }

    private static String endOfInput(UnexpectedEndOfInputException e) {
        JsonToken inside = e.getTokenBeingDecoded();
        if (inside == JsonToken.VALUE_STRING) {
            return "the scene ends inside a string";
        }
        if (inside == JsonToken.PROPERTY_NAME) {
            return "the scene ends inside a field name";
        }
        return e.getOriginalMessage() != null && e.getOriginalMessage().contains("comment")
                ? "the scene ends inside a comment (and comments are not allowed in JSON)"
                : "the scene ends before every object and array in it is closed";
    }

    /** A character by its code, as the user would recognise it: 'x', or U+0001 for one not printable. */
    private static String character(String code) {
        int c = Integer.parseInt(code);
        return c > 32 && c < 127 ? "'" + (char) c + "'" : codePoint(code);
    }

    /** An escape as it was written: \\q, or \\ and the code point of a character not printable. */
    private static String escaped(String code) {
        int c = Integer.parseInt(code);
        return c > 32 && c < 127 ? "\\" + (char) c : "\\ followed by " + codePoint(code);
    }

    private static String codePoint(String code) {
        return String.format("U+%04X", Integer.parseInt(code));
    }

    /** Text from the scene, quoted and cut short: the parser may quote a whole long run of garbage. */
    private static String quoted(String text) {
        return "'" + (text.length() > 40 ? text.substring(0, 40) + "…" : text) + "'";
    }

    private static String firstLine(String message) {
        if (message == null) {
            return "";
        }
        int nl = message.indexOf('\n');
        String line = nl < 0 ? message : message.substring(0, nl);
        return LOCATION_TRAILER.matcher(line).replaceAll("");
    }
}
