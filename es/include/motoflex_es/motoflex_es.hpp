#pragma once

// Everything of the optimiser library in one include.

#include "motoflex_es/checkpoint.hpp"
#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/driver.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/improvement_stall.hpp"
#include "motoflex_es/mpi_evaluator.hpp"
#include "motoflex_es/mpi_world.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "motoflex_es/nlopt_optimizer.hpp"
#include "motoflex_es/problem.hpp"
#include "motoflex_es/random.hpp"
#include "motoflex_es/strategy.hpp"
#include "motoflex_es/version.hpp"
