package studio.server.security;

import java.util.ArrayList;
import java.util.List;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.springframework.beans.factory.ObjectProvider;
import org.springframework.boot.context.properties.EnableConfigurationProperties;
import org.springframework.context.annotation.Bean;
import org.springframework.context.annotation.Configuration;
import org.springframework.security.authentication.AuthenticationManager;
import org.springframework.security.authentication.AuthenticationProvider;
import org.springframework.security.authentication.ProviderManager;
import org.springframework.security.config.annotation.web.builders.HttpSecurity;
import org.springframework.security.config.annotation.web.configuration.WebSecurityCustomizer;
import org.springframework.security.config.annotation.web.configurers.AbstractHttpConfigurer;
import org.springframework.security.config.http.SessionCreationPolicy;
import org.springframework.security.oauth2.jwt.JwtDecoder;
import org.springframework.security.oauth2.server.resource.authentication.JwtAuthenticationProvider;
import org.springframework.security.oauth2.server.resource.web.authentication.BearerTokenAuthenticationFilter;
import org.springframework.security.web.SecurityFilterChain;
import org.springframework.security.web.firewall.StrictHttpFirewall;

import jakarta.servlet.DispatcherType;
import studio.server.system.StudioProperties;
import tools.jackson.databind.json.JsonMapper;

/**
 * Sign-in (docs/security.md). Off by default: every request passes, as on one's own machine. On with
 * API keys ({@code studio.security.api-keys}) or JWTs (Spring's
 * {@code spring.security.oauth2.resourceserver.jwt.issuer-uri} or {@code .public-key-location}), or both:
 * every {@code /api/**} request, and the actuator's but liveness, readiness and the health's bare status,
 * then needs {@code Authorization: Bearer} (the live view also takes a ticket), and so does every other
 * path but the editor's files and the OpenAPI document, so that a browser can load the page and then ask
 * for a key. Stateless
 * bearer tokens: no session, no CSRF token.
 */
@Configuration(proxyBeanMethods = false)
@EnableConfigurationProperties(SignInProperties.class)
class SecurityConfiguration {

    private static final Logger log = LoggerFactory.getLogger("studio.security");
    /** What a browser loads before it has a key: the editor, the OpenAPI document and Swagger UI. */
    private static final String[] OPEN = {"/", "/index.html", "/assets/**", "/favicon.ico", "/v3/api-docs",
            "/v3/api-docs/**", "/swagger-ui.html", "/swagger-ui/**"};

    @Bean
    ApiKeys apiKeys(SignInProperties properties) {
        return ApiKeys.parse(properties.apiKeys());
    }

    @Bean
    SignIn signIn(SignInProperties properties, ApiKeys keys, ObjectProvider<JwtDecoder> jwt) {
        boolean jwts = jwt.getIfAvailable() != null;
        if (keys.size() == 0 && !jwts) {
            log.warn("Sign-in is off: anyone who reaches this port can render, read and cancel jobs and open live "
                    + "views; to turn it on, set studio.security.api-keys=NAME:KEY,... (or JWTs: docs/security.md)");
            return SignIn.OFF;
        }
        log.info("Sign-in is on: {} API key{}, JWTs {}", keys.size(), keys.size() == 1 ? "" : "s",
                jwts ? "accepted" : "off");
        return new SignIn(true, properties.maxJobsPerPrincipal(), properties.maxLiveViewsPerPrincipal());
    }

    @Bean
    PreviewTickets previewTickets(SignInProperties properties) {
        return new PreviewTickets(properties.ticketLifetime(), properties.maxTicketsPerPrincipal(),
                properties.maxTickets(), System::nanoTime);
    }

    @Bean
    SecurityFilterChain studioSecurity(HttpSecurity http, SignIn signIn, ApiKeys keys, ObjectProvider<JwtDecoder> jwt,
                                       PreviewTickets tickets, JsonMapper json) throws Exception {
        SecurityProblems problems = new SecurityProblems(json);
        http.csrf(AbstractHttpConfigurer::disable)
                .sessionManagement(session -> session.sessionCreationPolicy(SessionCreationPolicy.STATELESS))
                .httpBasic(AbstractHttpConfigurer::disable)
                .formLogin(AbstractHttpConfigurer::disable)
                .logout(AbstractHttpConfigurer::disable)
                .requestCache(AbstractHttpConfigurer::disable)
                .exceptionHandling(handling -> handling.authenticationEntryPoint(problems).accessDeniedHandler(problems));
        if (!signIn.required()) {
            http.authorizeHttpRequests(requests -> requests.anyRequest().permitAll());
            return http.build();
        }
        JwtDecoder decoder = jwt.getIfAvailable();
        List<AuthenticationProvider> providers = new ArrayList<>();
        providers.add(new ApiKeyAuthentication(keys, decoder != null));
        if (decoder != null) {
            providers.add(new JwtAuthenticationProvider(decoder)); // the token's sub is the principal
        }
        AuthenticationManager manager = new ProviderManager(providers);
        http.addFilterBefore(new TicketFilter(tickets, problems), BearerTokenAuthenticationFilter.class)
                .oauth2ResourceServer(server -> server.authenticationManagerResolver(request -> manager)
                        .authenticationEntryPoint(problems).accessDeniedHandler(problems))
                .authorizeHttpRequests(requests -> requests
                        // what an answered request dispatches to (its error page, its asynchronous end)
                        .dispatcherTypeMatchers(DispatcherType.ERROR, DispatcherType.ASYNC).permitAll()
                        // probes, and the bare status (details only for a signed-in caller: show-details)
                        .requestMatchers("/actuator/health", "/actuator/health/liveness", "/actuator/health/readiness")
                        .permitAll()
                        // the editor's files, the OpenAPI document and Swagger UI
                        .requestMatchers(OPEN).permitAll()
                        // the API, the actuator's other endpoints, and whatever is added later
                        .anyRequest().authenticated());
        return http.build();
    }

    /**
     * Spring Security's firewall, as strict as it is but for two things the service answered before sign-in
     * existed: a path parameter ({@code ;jsessionid=...}) is ignored, as Tomcat ignores it, and an unknown
     * method gets 405 from the API rather than 400 from the firewall. Path parameters do not confuse the
     * rules above: a request matcher compares the path without them, as Spring MVC routes it.
     */
    @Bean
    WebSecurityCustomizer firewall() {
        StrictHttpFirewall firewall = new StrictHttpFirewall();
        firewall.setAllowSemicolon(true);
        firewall.setUnsafeAllowAnyHttpMethod(true);
        return web -> web.httpFirewall(firewall);
    }
}
