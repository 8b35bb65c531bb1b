package studio.server.scene.reading;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Iterator;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.TokenStreamContext;
import tools.jackson.core.TokenStreamLocation;
import tools.jackson.core.exc.UnexpectedEndOfInputException;

import studio.server.scene.format.FieldProblem;

/**
 * Scene JSON the parser could not read, as one problem: the JSON path where the parser stopped and,
 * in the user's words ({@link ParserMessages}), why. The parser's own messages name no path (the
 * scene is read as a tree before any field is bound), but its context at the failure knows it: the
 * enclosing objects' current names and arrays' current indexes, from the root down.
 *
 * <p>Which field the innermost object's current name stands for depends on where in it the parser
 * failed. It has read that name and fails on its value (a colon, a number, NaN, the nesting limit):
 * the field is the name. It fails inside the string value it has just returned (invalid UTF-8, a
 * bad escape, a string too long): the name too. It has read a name it saw before (a duplicate): that
 * name. Otherwise it failed between fields (a missing comma, a broken next name, the end of input):
 * the field is the object itself.
 *
 * <p>Not a speed choice: Jackson's own messages name no field, and a 400 must ({@code MalformedJsonTest}).
 */
final class MalformedJson {

    /** What is wrong with anything after the scene's JSON object but white space. */
    static final String AFTER_THE_SCENE = "unexpected content after the scene's closing '}'";

    /** Longer paths (a scene nested 500 levels deep) keep their two ends, joined by an ellipsis. */
    static final int MAX_PATH_LENGTH = 300;

    private MalformedJson() {
    }

    /**
     * @param e      what the parser threw while reading {@code json}
     * @param parser the parser, as it stopped
     */
    static FieldProblem problem(JacksonException e, JsonParser parser, byte[] json) {
        TokenStreamLocation at = e.getLocation() != null && e.getLocation() != TokenStreamLocation.NA
                ? e.getLocation() : parser.currentLocation();
        TokenStreamContext context = parser.streamReadContext();
        if (context.inRoot() && context.getCurrentIndex() > 0) {
            return new FieldProblem("", "malformed JSON at line " + at.getLineNr() + ", column " + at.getColumnNr()
                    + ": " + AFTER_THE_SCENE);
        }
        String message = ParserMessages.describe(e, parser.streamReadConstraints(), at.getLineNr(), at.getColumnNr());
        return new FieldProblem(path(e, parser, json, at), message);
    }

    private static String path(JacksonException e, JsonParser parser, byte[] json, TokenStreamLocation at) {
        TokenStreamContext innermost = parser.streamReadContext();
        Deque<String> segments = new ArrayDeque<>();
        String last = innermostSegment(e, parser, json, at);
        if (last != null) {
            segments.push(last);
        }
        for (TokenStreamContext context = innermost.getParent(); context != null; context = context.getParent()) {
            String segment = segmentTo(context);
            if (segment != null) {
                segments.push(segment);
            }
        }
        return join(segments);
    }

    /** The innermost context's own segment, or null when the failure is about its container as a whole. */
    private static String innermostSegment(JacksonException e, JsonParser parser, byte[] json, TokenStreamLocation at) {
        TokenStreamContext context = parser.streamReadContext();
        JsonToken token = parser.currentToken();
        if (context.inArray()) {
            boolean betweenElements = e instanceof UnexpectedEndOfInputException end && end.getTokenBeingDecoded() == null;
            return betweenElements || !context.hasCurrentIndex() ? null : "[" + context.getCurrentIndex() + "]";
        }
        if (!context.inObject() || context.currentName() == null) {
            return null;
        }
        boolean onItsValue = token == JsonToken.PROPERTY_NAME
                || ParserMessages.isDuplicateName(e)
                || token == JsonToken.VALUE_STRING && insideString(json, parser.currentTokenLocation(), at);
        return onItsValue ? name(context.currentName()) : null;
    }

    /** The segment by which {@code context} leads to the value being read in it. */
    private static String segmentTo(TokenStreamContext context) {
        if (context.inArray()) {
            return "[" + context.getCurrentIndex() + "]";
        }
        if (context.inObject() && context.currentName() != null) {
            return name(context.currentName());
        }
        return null;
    }

    private static String name(String name) {
        return "." + name;
    }

    /**
     * Whether {@code failure} lies within the string token starting at {@code token} (its opening
     * quote), or the string is never closed. A JSON string ends at the first quote not escaped by a
     * backslash; no byte of a multi-byte UTF-8 character is a quote or a backslash.
     */
    private static boolean insideString(byte[] json, TokenStreamLocation token, TokenStreamLocation failure) {
        long start = token.getByteOffset();
        long failed = failure.getByteOffset();
        if (start < 0 || failed < 0 || start >= json.length || json[(int) start] != '"') {
            return false;
        }
        for (int i = (int) start + 1; i < json.length; i++) {
            if (json[i] == '\\') {
                i++;
            } else if (json[i] == '"') {
                return failed <= i;
            }
        }
        return true;
    }

    /**
     * The segments as a path (objects[0].material.color). A very long one keeps its two ends: 500
     * levels of names up to 50,000 characters each (the parser's limits) would otherwise make a
     * path of 25 MB.
     */
    private static String join(Deque<String> segments) {
        if (segments.isEmpty()) {
            return "";
        }
        String first = segments.pollFirst();
        segments.addFirst(first.startsWith(".") ? first.substring(1) : first);
        long length = 0;
        for (String segment : segments) {
            length += segment.length();
        }
        if (length <= MAX_PATH_LENGTH) {
            return String.join("", segments);
        }
        int half = (MAX_PATH_LENGTH - 1) / 2;
        StringBuilder head = new StringBuilder();
        for (String segment : segments) {
            if (head.length() + segment.length() > half) {
                head.append(head.isEmpty() ? segment.substring(0, half) : "");
                break;
            }
            head.append(segment);
        }
        StringBuilder tail = new StringBuilder();
        for (Iterator<String> it = segments.descendingIterator(); it.hasNext(); ) {
            String segment = it.next();
            if (tail.length() + segment.length() > half) {
                tail.insert(0, tail.isEmpty() ? segment.substring(segment.length() - half) : "");
                break;
            }
            tail.insert(0, segment);
        }
        return head + "…" + tail;
    }
}
