package studio.server.security;

import java.time.Duration;

import org.springframework.boot.context.properties.ConfigurationProperties;
import org.springframework.boot.context.properties.bind.DefaultValue;

/**
 * Sign-in (docs/security.md): off by default; on when API keys are set here, or JWTs are set up through
 * Spring's own {@code spring.security.oauth2.resourceserver.jwt.*} properties.
 *
 * @param apiKeys                  API keys as NAME:KEY,NAME:KEY; a request that sends
 *                                 "Authorization: Bearer KEY" acts as NAME. Also settable from a file or a
 *                                 Kubernetes Secret (spring.config.import=optional:configtree:/run/secrets/)
 * @param maxJobsPerPrincipal      with sign-in on, the most render jobs one principal may have queued or
 *                                 running on a member at once (0: half of studio.jobs.concurrent plus
 *                                 studio.jobs.queue); one more gets 429
 * @param maxLiveViewsPerPrincipal with sign-in on, the most live views one principal may have open on a
 *                                 member at once (0: half of studio.preview.max-sessions); one more gets 429
 * @param ticketLifetime           how long a live-view ticket (POST /api/preview/tickets) may wait to be used
 * @param maxTicketsPerPrincipal   unused live-view tickets one principal may hold at once
 * @param maxTickets               unused live-view tickets the server holds at once, over all principals
 */
@ConfigurationProperties("studio.security")
public record SignInProperties(@DefaultValue("") String apiKeys, @DefaultValue("0") int maxJobsPerPrincipal,
                               @DefaultValue("0") int maxLiveViewsPerPrincipal,
                               @DefaultValue("30s") Duration ticketLifetime,
                               @DefaultValue("8") int maxTicketsPerPrincipal, @DefaultValue("1024") int maxTickets) {
}
