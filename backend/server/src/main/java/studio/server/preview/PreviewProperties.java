package studio.server.preview;

import java.time.Duration;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.DefaultValue;

/**
 * The live view's limits (application.properties, or STUDIO_PREVIEW_MAXSESSIONS and so on).
 *
 * @param maxSessions  live views open at once; one more is refused with 503 and Retry-After
 * @param maxWidth     the largest view width a client may ask for
 * @param maxHeight    the largest view height
 * @param idleTimeout  a live view that sends nothing for this long is closed
 */
@ConfigurationProperties("studio.preview")
public record PreviewProperties(@DefaultValue("16") int maxSessions, @DefaultValue("2048") int maxWidth,
                                @DefaultValue("2048") int maxHeight, @DefaultValue("10m") Duration idleTimeout) {
}
