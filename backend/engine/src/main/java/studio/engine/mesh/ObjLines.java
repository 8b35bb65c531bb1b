package studio.engine.mesh;

import java.io.IOException;
import java.io.Reader;
import java.util.Arrays;

import studio.engine.memory.MemoryGate;

/**
 * OBJ text as lines of whitespace-separated tokens, and a token's value as a number or an index.
 * The text is read in chunks into one char buffer and each line is tokenised in place, without
 * regular expressions or a String per line or token; a '#' ends a line. Problems throw
 * {@link ObjFormatException} naming the current line.
 */
final class ObjLines {

    /**
     * Chars a read at most: a render process runs without on-stack replacement, so the JDK's copy
     * loop behind a read is compiled only after a hundred calls (docs/speed.md, "Where a cold process's time goes").
     */
    private static final int READ = 4096;

    private final Reader in;
    private final MemoryGate memory;
    /** Buffered text: the current line and what follows it; only the current chunk is held. */
    private char[] text;
    private int length;
    private boolean endOfInput, done;
    /** Where the next line starts, and where to look on for its end. */
    private int nextStart, scan;
    private int pos, lineEnd, line;
    private int tokenStart, tokenEnd;

    /** @param chars the buffer's first size, at least 2 (a line too long for it doubles it) */
    ObjLines(Reader in, int chars, MemoryGate memory) {
        this.in = in;
        this.memory = memory;
        memory.reserve(MemoryGate.chars(chars));
        text = new char[chars];
    }

    /** The current line's number, from 1. */
    int line() {
        return line;
    }

    /** Moves to the next line (an empty last line after a final newline is none); false at the end of the text. */
    boolean nextLine() throws IOException {
        while (!done) {
            int newline = scan;
            while (newline < length && text[newline] != '\n') {
                newline++;
            }
            if (newline < length || endOfInput) {
                boolean isLine = newline > nextStart || newline < length;
                pos = nextStart;
                lineEnd = newline;
                if (newline < length) {
                    nextStart = scan = newline + 1;
                } else {
                    done = true;
                }
                if (isLine) {
                    line++;
                    return true;
                }
                continue;
            }
            // The line runs past the buffered text: keep its start, read more.
            int kept = length - nextStart;
            if (kept == text.length) {
                memory.reserve(MemoryGate.chars(text.length * 2L));
                text = Arrays.copyOf(text, text.length * 2);
            } else if (nextStart > 0) {
                System.arraycopy(text, nextStart, text, 0, kept);
            }
            length = kept;
            nextStart = 0;
            scan = kept;
            int n = in.read(text, length, Math.min(READ, text.length - length));
            if (n < 0) {
                endOfInput = true;
            } else {
                length += n;
            }
        }
        return false;
    }

    /** Moves to the next token of the line; false at its end or at a '#'. */
    boolean nextToken() {
        while (pos < lineEnd && text[pos] <= ' ') {
            pos++;
        }
        if (pos >= lineEnd || text[pos] == '#') {
            pos = lineEnd;
            return false;
        }
        tokenStart = pos;
        while (pos < lineEnd && text[pos] > ' ') {
            pos++;
        }
        tokenEnd = pos;
        return true;
    }

    /** Whether the current token is {@code c}, or {@code c} then {@code second} (0: nothing). */
    boolean tokenIs(char c, char second) {
        int n = tokenEnd - tokenStart;
        return text[tokenStart] == c && (second == 0 ? n == 1 : n == 2 && text[tokenStart + 1] == second);
    }

    String token() {
        return new String(text, tokenStart, tokenEnd - tokenStart);
    }

    /**
     * The current token as a number, correctly rounded: a decimal as OBJ writers write them, checked
     * here (so no hexadecimal float or {@code f}/{@code d} suffix passes), then read by
     * {@link Double#parseDouble}; NaN for a spelled-out NaN or infinity, which the caller refuses.
     * A parser of its own saved 3-4 of the 100 ms of thread CPU time a 3.4 MB OBJ's upload takes, so none is kept.
     */
    double number() {
        int i = tokenStart, end = tokenEnd;
        if (i < end && (text[i] == '-' || text[i] == '+')) {
            i++;
        }
        int digits = 0;
        for (; i < end && text[i] >= '0' && text[i] <= '9'; i++) {
            digits++;
        }
        if (i < end && text[i] == '.') {
            for (i++; i < end && text[i] >= '0' && text[i] <= '9'; i++) {
                digits++;
            }
        }
        boolean wellFormed = true;
        if (digits > 0 && i < end && (text[i] == 'e' || text[i] == 'E')) {
            i++;
            if (i < end && (text[i] == '-' || text[i] == '+')) {
                i++;
            }
            int expDigits = 0;
            for (; i < end && text[i] >= '0' && text[i] <= '9'; i++) {
                expDigits++;
            }
            wellFormed = expDigits > 0;
        }
        String token = token();
        if (wellFormed && digits > 0 && i == end) {
            return Double.parseDouble(token);
        }
        String unsigned = token.startsWith("-") || token.startsWith("+") ? token.substring(1) : token;
        if (unsigned.equals("NaN") || unsigned.equals("Infinity")) {
            return Double.NaN;
        }
        throw new ObjFormatException(line, "'" + token + "' is not a number");
    }

    /** Where the next '/' of the current token lies from {@code from} on, or -1; the token's end is {@link #tokenEnd()}. */
    int slash(int from) {
        for (int i = from; i < tokenEnd; i++) {
            if (text[i] == '/') {
                return i;
            }
        }
        return -1;
    }

    int tokenStart() {
        return tokenStart;
    }

    int tokenEnd() {
        return tokenEnd;
    }

    /** The whole number in text[start, end) of the current token, signed, as an OBJ index is written. */
    int integer(int start, int end) {
        int i = start;
        boolean negative = false;
        if (i < end && (text[i] == '-' || text[i] == '+')) {
            negative = text[i] == '-';
            i++;
        }
        if (i == end || end - i > 10) {
            throw new ObjFormatException(line, "'" + token() + "' is not a valid index");
        }
        long value = 0;
        for (; i < end; i++) {
            char c = text[i];
            if (c < '0' || c > '9') {
                throw new ObjFormatException(line, "'" + token() + "' is not a valid index");
            }
            value = value * 10 + (c - '0');
        }
        if (value > Integer.MAX_VALUE) {
            throw new ObjFormatException(line, "index in '" + token() + "' is too large");
        }
        return negative ? (int) -value : (int) value;
    }
}
