# syntax=docker/dockerfile:1
# Three stages: Node builds the editor, the Maven wrapper builds the jar (JDK 17), a JDK 25 JRE runs it as a non-root user.

FROM node:20-bookworm-slim AS editor
WORKDIR /src/frontend
COPY frontend/package.json frontend/package-lock.json ./
RUN npm ci --no-audit --no-fund
COPY frontend/ ./
RUN npm run build

FROM eclipse-temurin:17-jdk AS jar
WORKDIR /src
COPY mvnw ./
COPY .mvn/ .mvn/
COPY backend/ backend/
COPY scenes/ scenes/
COPY --from=editor /src/frontend/dist frontend/dist
RUN ./mvnw -B -q -f backend/pom.xml package -DskipTests -DskipFrontend

# JDK 25 with the Vector API's incubator module (a boot module, so its JRE has it; the java
# -version below fails the build if not), so the engine can test four boxes at once (WideBoxTests)
FROM eclipse-temurin:25-jre
RUN java --add-modules jdk.incubator.vector -version \
    && apt-get update && apt-get install -y --no-install-recommends curl && rm -rf /var/lib/apt/lists/* \
    && groupadd --system --gid 10001 studio \
    && useradd --system --uid 10001 --gid 10001 --home-dir /app studio
WORKDIR /app
COPY --from=jar /src/backend/server/target/studio.jar studio.jar
USER 10001:10001
EXPOSE 8080
ENV JAVA_TOOL_OPTIONS="-XX:MaxRAMPercentage=75 -XX:+ExitOnOutOfMemoryError"
HEALTHCHECK --interval=15s --timeout=3s --start-period=30s --retries=3 \
    CMD curl -fsS http://localhost:8080/actuator/health || exit 1
ENTRYPOINT ["java", "--add-modules", "jdk.incubator.vector", "-jar", "/app/studio.jar"]
