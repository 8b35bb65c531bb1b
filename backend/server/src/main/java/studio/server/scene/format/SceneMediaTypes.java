package studio.server.scene.format;

/**
 * The media types a scene may be posted as: JSON only. A browser sends text/plain, form and
 * multipart bodies to another site without asking it first (no CORS preflight), so if those were
 * read as scenes, any web page could make its visitors start renders here; a JSON body it cannot
 * send to another site without that site's consent. Anything else is refused with 415.
 */
public final class SceneMediaTypes {

    public static final String JSON = "application/json";
    /** A JSON-based type of the client's own (application/vnd.example+json). */
    public static final String JSON_SUFFIXED = "application/*+json";

    private SceneMediaTypes() {
    }
}
