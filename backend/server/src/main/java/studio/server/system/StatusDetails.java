package studio.server.system;

import org.springframework.http.HttpStatus;

/**
 * What an error status means, in the user's words, for an error that comes with nothing but its
 * status: one the servlet container answers itself (ProblemReportValve), or one it hands to /error
 * (ProblemErrorController) without an exception the application knows.
 */
final class StatusDetails {

    private StatusDetails() {
    }

    /** The problem's title: the status's reason phrase. */
    static String title(int status) {
        HttpStatus known = HttpStatus.resolve(status);
        return known != null ? known.getReasonPhrase() : status < 500 ? "Client Error" : "Server Error";
    }

    static String detail(int status) {
        return switch (status) {
            case 400 -> "the request cannot be read: its request line, headers or body break the rules of HTTP";
            case 404 -> "there is nothing at this path";
            case 405 -> "this method is not allowed here";
            case 408 -> "the request took too long to arrive";
            case 411 -> "the request needs a Content-Length";
            case 413 -> "the request is too large";
            case 414 -> "the URL is too long";
            case 415 -> "the body's media type is not accepted here";
            case 417 -> "the server meets no expectation but 100-continue";
            case 431 -> "the request's headers are too large";
            case 500 -> "an unexpected error occurred; it has been logged";
            case 501 -> "the server does not support what the request asks for (a Transfer-Encoding other than "
                    + "chunked, or the CONNECT method)";
            case 503 -> "the server cannot take the request now (it is starting or stopping); try again shortly";
            case 505 -> "the request's HTTP version is not supported; use HTTP/1.1";
            default -> status < 500 ? "the request was refused (" + title(status) + ")"
                    : "the server could not answer the request (" + title(status) + ")";
        };
    }
}
