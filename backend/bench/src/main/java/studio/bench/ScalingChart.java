package studio.bench;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.XYStyler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The scaling chart: render time and build time (ms) against the number of objects or triangles
 * (log x), spheres in blue, triangles in orange, render solid, build dashed.
 */
final class ScalingChart {

    static final int WIDTH = 760, HEIGHT = 460;
    private static final Color SPHERES = new Color(0x1f77b4), TRIANGLES = new Color(0xff7f0e);

    private ScalingChart() {
    }

    static void write(List<ScalingCommand.Row> rows, Path png) throws IOException {
        ImageIO.write(BitmapEncoder.getBufferedImage(chart(rows)), "png", png.toFile());
    }

    static XYChart chart(List<ScalingCommand.Row> rows) {
        XYChart chart = new XYChartBuilder().width(WIDTH).height(HEIGHT)
                .title("Render and build time against scene size (800x600, 1 sample per pixel)")
                .xAxisTitle("spheres, or triangles in one mesh").yAxisTitle("time (ms)").build();
        XYStyler style = chart.getStyler();
        style.setXAxisLogarithmic(true);
        style.setXAxisDecimalPattern("#,###");
        style.setLegendPosition(Styler.LegendPosition.InsideNW);
        style.setLegendBorderColor(Color.WHITE);
        style.setChartBackgroundColor(Color.WHITE);
        style.setPlotBackgroundColor(Color.WHITE);
        style.setPlotGridLinesColor(new Color(0xe4e4e4));
        style.setPlotGridLinesStroke(new BasicStroke(0.5f));
        style.setChartTitleFont(new Font(Font.SANS_SERIF, Font.BOLD, 14));
        style.setAxisTitleFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        style.setAxisTickLabelsFont(new Font(Font.SANS_SERIF, Font.PLAIN, 10));
        style.setLegendFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        style.setMarkerSize(7);
        style.setYAxisMin(0.0);
        add(chart, rows, "spheres", "spheres: render", SPHERES, true);
        add(chart, rows, "spheres", "spheres: build", SPHERES, false);
        add(chart, rows, "triangles", "triangles: render", TRIANGLES, true);
        add(chart, rows, "triangles", "triangles: build", TRIANGLES, false);
        return chart;
    }

    private static void add(XYChart chart, List<ScalingCommand.Row> rows, String series, String name, Color color,
                            boolean render) {
        List<ScalingCommand.Row> own = rows.stream().filter(r -> r.series().equals(series)).toList();
        if (own.isEmpty()) {
            return;
        }
        double[] x = own.stream().mapToDouble(ScalingCommand.Row::count).toArray();
        double[] y = own.stream().mapToDouble(r -> (render ? r.medianRenderNanos() : r.buildNanos()) / 1e6).toArray();
        XYSeries s = chart.addSeries(name, x, y);
        s.setLineColor(color);
        s.setMarkerColor(color);
        s.setMarker(render ? SeriesMarkers.CIRCLE : SeriesMarkers.SQUARE);
        s.setLineStyle(render ? SeriesLines.SOLID : SeriesLines.DASH_DASH);
    }
}
