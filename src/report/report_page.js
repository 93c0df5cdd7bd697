// Draws the figures of a motoflex report (inlined into report.html after plotly.js by
// src/report/report_page.cpp). The data are the page's <script id="motoflex-data"> JSON; the
// markup (divs, joint selectors) is written by the report generator. A figure that fails shows
// its error in its place and on the console, so that the rest of the page still draws and a
// headless browser test sees the failure.
(function () {
  'use strict';
  var data = JSON.parse(document.getElementById('motoflex-data').textContent);
  var config = {responsive: true, displaylogo: false, modeBarButtonsToRemove: ['select2d', 'lasso2d']};
  var drawn = 0;
  var failed = 0;

  function guard(id, draw) {
    var div = document.getElementById(id);
    if (!div) return;
    try {
      draw(div);
      drawn += 1;
    } catch (error) {
      failed += 1;
      div.innerHTML = '';
      var message = document.createElement('p');
      message.className = 'plot-error';
      message.textContent = 'This figure could not be drawn: ' + error;
      div.appendChild(message);
      console.error('motoflex report: ' + id + ': ' + error);
    }
  }

  // Fitness is positive; a log axis cannot show zero or non-finite values, so they are gaps.
  function positive(values) {
    return values.map(function (v) { return v !== null && isFinite(v) && v > 0 ? v : null; });
  }

  function drawConvergence(div) {
    var c = data.convergence;
    var traces = [
      {x: c.generation, y: positive(c.best), name: 'best so far', mode: 'lines+markers',
       line: {color: '#1f5fbf', width: 2}, marker: {size: 4},
       customdata: c.evaluations, hovertemplate: 'generation %{x}<br>%{customdata} evaluations<br>best %{y:.4g}<extra></extra>'},
      {x: c.generation, y: positive(c.median), name: 'median of the generation', mode: 'lines',
       line: {color: '#e08a1e', width: 1.5, dash: 'dot'},
       hovertemplate: 'generation %{x}<br>median %{y:.4g}<extra></extra>'}
    ];
    var layout = {
      margin: {l: 70, r: 20, t: 10, b: 45},
      // A short run would get ticks at 1.2, 1.4, ...; a long one gets whole numbers anyway.
      xaxis: c.generation.length <= 12 ? {title: {text: 'generation'}, tick0: 0, dtick: 1}
                                       : {title: {text: 'generation'}},
      yaxis: {title: {text: 'fitness F'}, type: 'log', exponentformat: 'power'},
      legend: {orientation: 'h', x: 0, y: 1.08}
    };
    Plotly.newPlot(div, traces, layout, config);
  }

  function residual(measured, simulated) {
    return measured.map(function (m, i) {
      var s = simulated[i];
      return m === null || s === null ? null : m - s;
    });
  }

  function logFigure(log, channel) {
    var t = channel.t || log.t;
    var traces = [
      {x: t, y: channel.measured, name: 'measured', mode: 'lines', line: {color: '#1d2330', width: 1.5},
       xaxis: 'x', yaxis: 'y'},
      {x: t, y: channel.simulated, name: 'simulated (best)', mode: 'lines',
       line: {color: '#d0431b', width: 1.5, dash: 'dash'}, xaxis: 'x', yaxis: 'y'},
      {x: t, y: residual(channel.measured, channel.simulated), name: 'residual (measured − simulated)',
       mode: 'lines', line: {color: '#2a8a4a', width: 1.2}, xaxis: 'x', yaxis: 'y2'}
    ];
    var shapes = [{type: 'line', xref: 'paper', x0: 0, x1: 1, yref: 'y2', y0: 0, y1: 0,
                   line: {color: '#9aa3b2', width: 1}}];
    var lastT = log.t.length ? log.t[log.t.length - 1] : 0;
    if (log.frames_simulated > 0 && log.simulated_end_s < lastT - 1e-9) {
      shapes.push({type: 'line', xref: 'x', x0: log.simulated_end_s, x1: log.simulated_end_s,
                   yref: 'paper', y0: 0, y1: 1, line: {color: '#d0431b', width: 1, dash: 'dot'}});
    }
    var layout = {
      margin: {l: 70, r: 20, t: 10, b: 45},
      xaxis: {title: {text: 'time (s)'}, anchor: 'y2'},
      yaxis: {domain: [0.36, 1], title: {text: channel.name + ' (deg)'}},
      yaxis2: {domain: [0, 0.28], title: {text: 'residual (deg)'}},
      legend: {orientation: 'h', x: 0, y: 1.09},
      shapes: shapes,
      hovermode: 'x unified'
    };
    return {traces: traces, layout: layout};
  }

  // Values where both coherences reach the threshold, gaps elsewhere.
  function coherent(values, f, threshold) {
    return values.map(function (v, i) {
      var ok = f.measured.coherence[i] !== null && f.simulated.coherence[i] !== null &&
               f.measured.coherence[i] >= threshold && f.simulated.coherence[i] >= threshold;
      return ok ? v : null;
    });
  }

  function bodeFigure(channel) {
    var f = channel.frequency;
    var c = data.min_coherence;
    var traces = [
      {x: f.f_hz, y: coherent(f.measured.gain_db, f, c), name: 'measured', mode: 'lines+markers',
       line: {color: '#1d2330', width: 1.5}, marker: {size: 3}, xaxis: 'x', yaxis: 'y'},
      {x: f.f_hz, y: coherent(f.simulated.gain_db, f, c), name: 'simulated (best)',
       mode: 'lines+markers', line: {color: '#d0431b', width: 1.5, dash: 'dash'}, marker: {size: 3},
       xaxis: 'x', yaxis: 'y'},
      {x: f.f_hz, y: coherent(f.measured.phase_deg, f, c), showlegend: false, mode: 'lines+markers',
       line: {color: '#1d2330', width: 1.5}, marker: {size: 3}, xaxis: 'x', yaxis: 'y2'},
      {x: f.f_hz, y: coherent(f.simulated.phase_deg, f, c), showlegend: false,
       mode: 'lines+markers', line: {color: '#d0431b', width: 1.5, dash: 'dash'}, marker: {size: 3},
       xaxis: 'x', yaxis: 'y2'},
      {x: f.f_hz, y: f.measured.coherence, name: 'coherence γ², measured', mode: 'lines',
       line: {color: '#6b7890', width: 1}, xaxis: 'x', yaxis: 'y3'},
      {x: f.f_hz, y: f.simulated.coherence, name: 'coherence γ², simulated', mode: 'lines',
       line: {color: '#e08a1e', width: 1, dash: 'dot'}, xaxis: 'x', yaxis: 'y3'}
    ];
    var layout = {
      margin: {l: 70, r: 20, t: 10, b: 45},
      xaxis: {title: {text: 'frequency (Hz)'}, type: 'log', anchor: 'y3'},
      yaxis: {domain: [0.56, 1], title: {text: 'gain (dB)'}},
      yaxis2: {domain: [0.24, 0.5], title: {text: 'phase (deg)'}},
      yaxis3: {domain: [0, 0.16], range: [0, 1.05], title: {text: 'γ²'}},
      shapes: [{type: 'line', xref: 'paper', x0: 0, x1: 1, yref: 'y3', y0: c, y1: c,
                line: {color: '#9aa3b2', width: 1, dash: 'dot'}}],
      legend: {orientation: 'h', x: 0, y: 1.1},
      hovermode: 'x unified'
    };
    return {traces: traces, layout: layout};
  }

  // The selected channel's frequency response, or why there is none.
  function drawBode(index, channel) {
    var id = 'log-' + index + '-bode';
    var div = document.getElementById(id);
    if (!div) return;
    var why = null;
    if (!channel.frequency) {
      why = 'No frequency response for ' + channel.name +
        ' (an IMU angle, a log without commands, or a command that does not move).';
    } else if (!channel.frequency.coherent_points) {
      why = 'No frequency response for ' + channel.name + ': nowhere do both coherences reach ' +
        data.min_coherence + ' (the command does not excite the joint over a band, or the joint ' +
        'does not follow it linearly: steps and holds give none, chirps and multisines do).';
    }
    Plotly.purge(div);
    if (why) {
      div.style.height = 'auto';
      div.innerHTML = '';
      var note = document.createElement('p');
      note.className = 'note';
      note.textContent = why;
      div.appendChild(note);
      return;
    }
    div.style.height = '';
    div.innerHTML = '';
    guard(id, function (target) {
      var figure = bodeFigure(channel);
      Plotly.react(target, figure.traces, figure.layout, config);
    });
  }

  function drawLog(index) {
    var log = data.logs[index];
    var select = document.getElementById('log-' + index + '-channel');
    var selected = function () { return log.channels[select ? Number(select.value) : 0]; };
    var draw = function (div) {
      var figure = logFigure(log, selected());
      Plotly.react(div, figure.traces, figure.layout, config);
    };
    guard('log-' + index + '-plot', draw);
    drawBode(index, selected());
    if (select) {
      select.addEventListener('change', function () {
        guard('log-' + index + '-plot', draw);
        drawBode(index, selected());
      });
    }
  }

  function drawCorrelation(div) {
    var c = data.correlation;
    var n = c.names.length;
    var trace = {
      type: 'heatmap', z: c.matrix, x: c.names, y: c.names, zmin: -1, zmax: 1,
      colorscale: 'RdBu', reversescale: true, texttemplate: '%{z:.2f}',
      hovertemplate: '%{y}<br>%{x}<br>correlation %{z:.3f}<extra></extra>',
      colorbar: {title: {text: 'ρ'}}
    };
    var layout = {
      margin: {l: 220, r: 20, t: 10, b: 160},
      height: Math.max(320, 140 + 36 * n),
      xaxis: {tickangle: -35}, yaxis: {autorange: 'reversed'}
    };
    Plotly.newPlot(div, [trace], layout, config);
  }

  if (data.convergence) guard('convergence', drawConvergence);
  for (var i = 0; i < data.logs.length; i += 1) {
    if (data.logs[i].channels.length) drawLog(i);
  }
  if (data.correlation) guard('correlation', drawCorrelation);
  document.body.setAttribute('data-figures-drawn', String(drawn));
  document.body.setAttribute('data-figures-failed', String(failed));
})();
